#include "core/solid/cell_windings.h"

#include "core/util/union_find.h"

#include <algorithm>
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
// looking against d), starting from the first face. Exact: no angle is computed, the
// half-plane and the sign of a cross product decide.
void sortAroundEdge(const RefinedSoup& soup, const ExactPoint& a, const ExactVector& d, std::vector<EdgeFace>& faces)
{
    const auto across = [&](const EdgeFace& e) {
        const ExactVector u = soup.points[e.third] - a;
        return u * (d * d) - d * (u * d); // u without its part along d (scaled)
    };
    const ExactVector e1 = across(faces.front());
    const ExactVector e2 = CGAL::cross_product(d, e1);
    struct Keyed {
        EdgeFace face;
        ExactKernel::FT x, y;
        int half; ///< 0: angle in [0, pi), 1: [pi, 2 pi)
    };
    std::vector<Keyed> keyed;
    keyed.reserve(faces.size());
    for (const EdgeFace& e : faces) {
        const ExactVector u = across(e);
        Keyed k{e, u * e1, u * e2, 0};
        k.half = (CGAL::is_negative(k.y) || (CGAL::is_zero(k.y) && CGAL::is_negative(k.x))) ? 1 : 0;
        keyed.push_back(std::move(k));
    }
    std::stable_sort(keyed.begin(), keyed.end(), [](const Keyed& p, const Keyed& q) {
        if (p.half != q.half)
            return p.half < q.half;
        return CGAL::is_positive(p.x * q.y - p.y * q.x);
    });
    for (std::size_t i = 0; i < faces.size(); ++i)
        faces[i] = keyed[i].face;
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

// Joins the two face sides that look into each wedge between consecutive faces.
void joinWedges(const RefinedSoup& soup, UnionFind& sides)
{
    for (auto& [key, faces] : edgeFaces(soup)) {
        if (faces.size() < 2)
            continue; // an open edge: the windings are not defined there (counted as contradictions)
        const std::uint32_t a = std::uint32_t(key >> 32);
        // Two faces are in order whatever their angles; more (along an intersection
        // curve) are sorted exactly.
        if (faces.size() > 2)
            sortAroundEdge(soup, soup.points[a], soup.points[std::uint32_t(key & 0xffffffffu)] - soup.points[a], faces);
        for (std::size_t i = 0; i < faces.size(); ++i) {
            const EdgeFace& f = faces[i];
            const EdgeFace& g = faces[(i + 1) % faces.size()];
            const std::size_t sideOfF = frontFacesGrowingAngle(soup, a, f) ? frontSide(f.face) : backSide(f.face);
            const std::size_t sideOfG = frontFacesGrowingAngle(soup, a, g) ? backSide(g.face) : frontSide(g.face);
            sides.unite(sideOfF, sideOfG);
        }
    }
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
    const std::size_t faceCount = soup.faces.size();
    UnionFind sides(2 * faceCount);
    joinWedges(soup, sides);
    control.throwIfCancelled();

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
    CellWindings result;
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
        const std::vector<int> absolute = absoluteFront(soup, seed, reach);
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
