#include "core/solid/cell_windings.h"

#include "core/util/union_find.h"

#include <algorithm>
#include <chrono>
#include <optional>
#include <queue>
#include <unordered_map>

namespace trimlab::solid {

namespace {

// Face side ids: 2f is the front of face f, 2f + 1 its back.
std::size_t frontSide(std::size_t f)
{
    return 2 * f;
}
std::size_t backSide(std::size_t f)
{
    return 2 * f + 1;
}

ExactVector faceNormal(const RefinedSoup& soup, std::size_t f)
{
    const auto& v = soup.faces[f].vertices;
    return CGAL::cross_product(soup.points[v[1]] - soup.points[v[0]], soup.points[v[2]] - soup.points[v[0]]);
}

struct EdgeFace {
    std::size_t face;
    std::uint32_t third; ///< the face's vertex off the edge
};

std::unordered_map<std::uint64_t, std::vector<EdgeFace>> edgeFaces(const RefinedSoup& soup)
{
    std::unordered_map<std::uint64_t, std::vector<EdgeFace>> edges;
    for (std::size_t f = 0; f < soup.faces.size(); ++f) {
        const auto& v = soup.faces[f].vertices;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = v[std::size_t(k)], b = v[std::size_t((k + 1) % 3)];
            const std::uint64_t key = (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
            edges[key].push_back({f, v[std::size_t((k + 2) % 3)]});
        }
    }
    return edges;
}

// Sorts the faces around edge (a, b) by their angle about d = b - a (counter-clockwise
// looking against d), starting from the first face. Exact, by orientation predicates on
// the points alone (no construction): a face's third corner c lies in the half-turn
// after the first face's when orientation(a, b, c_first, c) is positive, and of two in
// one half-turn p comes first when orientation(a, b, c_p, c_q) is. Faces of one source
// lie in one plane, on opposite sides of the edge: half a turn apart, decided without
// the predicate that would be exactly zero (and fall back to rationals).
void sortAroundEdge(const RefinedSoup& soup, std::uint32_t a, std::uint32_t b, std::vector<EdgeFace>& faces)
{
    const ExactPoint& A = soup.points[a];
    const ExactPoint& B = soup.points[b];
    const EdgeFace first = faces.front();
    const ExactPoint& reference = soup.points[first.third];
    const auto halfTurn = [&](const EdgeFace& e) { // 0: angle in [0, pi), 1: [pi, 2 pi)
        if (e.face == first.face)
            return 0;
        if (soup.faces[e.face].source == soup.faces[first.face].source)
            return 1;
        const ExactPoint& c = soup.points[e.third];
        const CGAL::Orientation side = CGAL::orientation(A, B, reference, c);
        if (side != CGAL::COPLANAR)
            return side == CGAL::POSITIVE ? 0 : 1;
        return CGAL::coplanar_orientation(A, B, reference, c) == CGAL::POSITIVE ? 0 : 1;
    };
    std::vector<std::pair<int, EdgeFace>> keyed;
    keyed.reserve(faces.size());
    for (const EdgeFace& e : faces)
        keyed.emplace_back(halfTurn(e), e);
    std::stable_sort(keyed.begin(), keyed.end(), [&](const auto& p, const auto& q) {
        if (p.first != q.first)
            return p.first < q.first;
        return CGAL::orientation(A, B, soup.points[p.second.third], soup.points[q.second.third]) == CGAL::POSITIVE;
    });
    for (std::size_t i = 0; i < faces.size(); ++i)
        faces[i] = keyed[i].second;
}

// Whether face f's front looks towards growing angles about d = b - a at the edge: its
// normal is (b - a) x (c - a) when it runs a -> b, the opposite when it runs b -> a, and
// the rotation's tangent at f is d x (c - a); so it is a matter of f's vertex order.
bool frontFacesGrowingAngle(const RefinedSoup& soup, std::uint32_t a, const EdgeFace& e)
{
    const auto& v = soup.faces[e.face].vertices;
    for (int k = 0; k < 3; ++k)
        if (v[std::size_t(k)] == a)
            return v[std::size_t((k + 2) % 3)] == e.third; // a -> b -> third
    return false;
}

// Joins the two face sides that look into each wedge between consecutive faces; returns
// the number of edges sorted.
std::size_t joinWedges(const RefinedSoup& soup, UnionFind& sides)
{
    std::size_t sorted = 0;
    for (auto& [key, faces] : edgeFaces(soup)) {
        if (faces.size() < 2)
            continue; // an open edge: the windings are not defined there (counted as contradictions)
        const std::uint32_t a = std::uint32_t(key >> 32);
        // Two faces are in order whatever their angles; more (along an intersection
        // curve) are sorted exactly.
        if (faces.size() > 2) {
            sortAroundEdge(soup, a, std::uint32_t(key & 0xffffffffu), faces);
            ++sorted;
        }
        for (std::size_t i = 0; i < faces.size(); ++i) {
            const EdgeFace& f = faces[i];
            const EdgeFace& g = faces[(i + 1) % faces.size()];
            const std::size_t sideOfF = frontFacesGrowingAngle(soup, a, f) ? frontSide(f.face) : backSide(f.face);
            const std::size_t sideOfG = frontFacesGrowingAngle(soup, a, g) ? backSide(g.face) : frontSide(g.face);
            sides.unite(sideOfF, sideOfG);
        }
    }
    return sorted;
}

// The winding numbers just in front of face `start` (at its centroid), by counting the
// faces a ray from there to beyond the bounding box crosses. nullopt when the ray grazes
// an edge or a vertex or runs in a face's plane through it (try another direction).
std::optional<std::vector<int>> rayWindings(const RefinedSoup& soup, std::size_t start, const ExactVector& direction,
                                            const ExactKernel::FT& reach)
{
    const auto& v = soup.faces[start].vertices;
    const ExactPoint p = CGAL::centroid(soup.points[v[0]], soup.points[v[1]], soup.points[v[2]]);
    const ExactKernel::FT largest =
        std::max({CGAL::abs(direction.x()), CGAL::abs(direction.y()), CGAL::abs(direction.z())});
    const ExactPoint q = p + direction * (reach / largest);
    std::vector<int> windings(soup.faces[start].delta.size(), 0);
    for (std::size_t g = 0; g < soup.faces.size(); ++g) {
        if (g == start)
            continue;
        const auto& w = soup.faces[g].vertices;
        const ExactPoint& A = soup.points[w[0]];
        const ExactPoint& B = soup.points[w[1]];
        const ExactPoint& C = soup.points[w[2]];
        const CGAL::Orientation o1 = CGAL::orientation(A, B, C, p);
        const CGAL::Orientation o2 = CGAL::orientation(A, B, C, q);
        if (o1 == CGAL::COPLANAR && o2 == CGAL::COPLANAR) {
            if (CGAL::do_intersect(ExactKernel::Segment_3(p, q), ExactKernel::Triangle_3(A, B, C)))
                return std::nullopt;
            continue;
        }
        if (o1 == o2 || o1 == CGAL::COPLANAR || o2 == CGAL::COPLANAR)
            continue; // no crossing beyond the start (p lies in g's plane only outside g)
        const CGAL::Orientation s1 = CGAL::orientation(p, q, A, B);
        const CGAL::Orientation s2 = CGAL::orientation(p, q, B, C);
        const CGAL::Orientation s3 = CGAL::orientation(p, q, C, A);
        const bool anyPositive = s1 == CGAL::POSITIVE || s2 == CGAL::POSITIVE || s3 == CGAL::POSITIVE;
        const bool anyNegative = s1 == CGAL::NEGATIVE || s2 == CGAL::NEGATIVE || s3 == CGAL::NEGATIVE;
        if (anyPositive && anyNegative)
            continue; // passes beside the triangle
        if (s1 == CGAL::COPLANAR || s2 == CGAL::COPLANAR || s3 == CGAL::COPLANAR)
            return std::nullopt; // through an edge or a vertex
        // From g's back to its front (towards infinity) the winding drops by g's delta.
        const int sign = o1 == CGAL::NEGATIVE ? 1 : -1;
        for (std::size_t o = 0; o < windings.size(); ++o)
            windings[o] += sign * soup.faces[g].delta[o];
    }
    return windings;
}

std::vector<int> absoluteFront(const RefinedSoup& soup, std::size_t start, const ExactKernel::FT& reach)
{
    const ExactVector n = faceNormal(soup, start);
    const ExactKernel::FT scale = std::max({CGAL::abs(n.x()), CGAL::abs(n.y()), CGAL::abs(n.z())});
    // The normal first, then tilted ever so slightly in irregular ways; all look to the front.
    for (int k = 0; k < 64; ++k) {
        const ExactVector tilt(scale * k * 37 / 1000, scale * k * 53 / 1000 * ((k % 2) ? 1 : -1),
                               scale * k * 71 / 1000);
        const ExactVector direction = n * 8 + tilt / 8;
        if (!CGAL::is_positive(direction * n))
            continue;
        if (std::optional<std::vector<int>> w = rayWindings(soup, start, direction, reach))
            return *w;
    }
    throw std::runtime_error("no ray from a face of the trimmed solid avoids every edge and vertex");
}

ExactKernel::FT boundingReach(const RefinedSoup& soup)
{
    ExactKernel::FT reach = 1;
    for (const ExactPoint& p : soup.points)
        reach = std::max({reach, CGAL::abs(p.x()), CGAL::abs(p.y()), CGAL::abs(p.z())});
    return reach * 4;
}

} // namespace

CellWindings cellWindings(const RefinedSoup& soup, const TaskControl& control)
{
    auto start = std::chrono::steady_clock::now();
    const auto lap = [&start](double& ms) {
        const auto now = std::chrono::steady_clock::now();
        ms += std::chrono::duration<double, std::milli>(now - start).count();
        start = now;
    };
    CellWindings result;
    const std::size_t faceCount = soup.faces.size();
    UnionFind sides(2 * faceCount);
    result.sortedEdges = joinWedges(soup, sides);
    control.throwIfCancelled();
    lap(result.wedgesMs);

    // Groups, and the faces between them: behind = in front + delta.
    std::unordered_map<std::size_t, std::size_t> groupOf;
    std::vector<std::vector<std::size_t>> facesOfGroup;
    const auto group = [&](std::size_t side) {
        const auto [it, inserted] = groupOf.emplace(sides.find(side), facesOfGroup.size());
        if (inserted)
            facesOfGroup.emplace_back();
        return it->second;
    };
    std::vector<std::size_t> frontGroup(faceCount), backGroup(faceCount);
    for (std::size_t f = 0; f < faceCount; ++f) {
        frontGroup[f] = group(frontSide(f));
        backGroup[f] = group(backSide(f));
        facesOfGroup[frontGroup[f]].push_back(f);
        facesOfGroup[backGroup[f]].push_back(f);
    }
    result.boundaryPieces = facesOfGroup.size();
    const std::size_t objects = faceCount > 0 ? soup.faces.front().delta.size() : 0;
    std::vector<std::optional<std::vector<int>>> winding(facesOfGroup.size());
    const ExactKernel::FT reach = boundingReach(soup);
    for (std::size_t seed = 0; seed < faceCount; ++seed) {
        if (winding[frontGroup[seed]])
            continue;
        // A new connected piece: relative windings by a walk across its faces...
        ++result.components;
        std::vector<std::size_t> members{frontGroup[seed]};
        winding[frontGroup[seed]] = std::vector<int>(objects, 0);
        std::queue<std::size_t> open;
        open.push(frontGroup[seed]);
        while (!open.empty()) {
            const std::size_t g = open.front();
            open.pop();
            for (std::size_t f : facesOfGroup[g]) {
                const bool fromFront = frontGroup[f] == g;
                const std::size_t other = fromFront ? backGroup[f] : frontGroup[f];
                std::vector<int> w = *winding[g];
                for (std::size_t o = 0; o < objects; ++o)
                    w[o] += (fromFront ? 1 : -1) * soup.faces[f].delta[o];
                if (!winding[other]) {
                    winding[other] = std::move(w);
                    members.push_back(other);
                    open.push(other);
                } else if (*winding[other] != w) {
                    ++result.contradictions;
                }
            }
        }
        // ... then one ray fixes the piece's offset.
        lap(result.walkMs);
        const std::vector<int> absolute = absoluteFront(soup, seed, reach);
        lap(result.raysMs);
        for (std::size_t g : members)
            for (std::size_t o = 0; o < objects; ++o)
                (*winding[g])[o] += absolute[o];
        control.throwIfCancelled();
    }
    result.contradictions /= 2; // each inconsistent face is met from both of its groups
    result.front.resize(faceCount);
    for (std::size_t f = 0; f < faceCount; ++f)
        result.front[f] = *winding[frontGroup[f]];
    return result;
}

} // namespace trimlab::solid
