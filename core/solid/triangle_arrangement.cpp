#include "core/solid/triangle_arrangement.h"

#include "core/util/parallel_for.h"
#include "core/util/union_find.h"

#include <CGAL/Constrained_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <utility>

namespace trimlab::solid {

namespace {

using Triangle3 = ExactKernel::Triangle_3;
using Segment3 = ExactKernel::Segment_3;
using Plane3 = ExactKernel::Plane_3;
using Point2 = ExactKernel::Point_2;
using Triangle2 = ExactKernel::Triangle_2;
using FT = ExactKernel::FT;

// The triangulation of one plane: vertices remember the 3D point they were inserted for;
// those the triangulation creates where two constraints cross are lifted back onto the
// plane. Exact_intersections_tag: crossing constraints are split at their exact crossing.
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<std::optional<ExactPoint>, ExactKernel>;
using FaceBase = CGAL::Constrained_triangulation_face_base_2<ExactKernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using PlaneTriangulation = CGAL::Constrained_triangulation_2<ExactKernel, Tds, CGAL::Exact_intersections_tag>;

using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;

// Corners are kept as points, not read from a Triangle_3: each corner read from a lazy
// exact triangle builds a new lazy construction (measured: the largest single cost).
using Corners = std::array<ExactPoint, 3>;

// The input corners are doubles, so predicates on them are exact in the kernel of exact
// predicates and double constructions, which decides them without allocating: pairs of
// triangles are sorted out there, and only those that really cross reach the lazy kernel.
using InputKernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using InputPoint = InputKernel::Point_3;
using InputCorners = std::array<InputPoint, 3>;

/// What other triangles leave on a triangle: points where they touch it, segments where
/// they cross it.
struct Marks {
    std::vector<ExactPoint> points;
    std::vector<std::array<ExactPoint, 2>> segments;
};

std::vector<std::pair<std::size_t, std::size_t>> overlappingBoxes(const std::vector<Corners>& triangles)
{
    std::vector<Box> boxes;
    boxes.reserve(triangles.size());
    for (std::size_t i = 0; i < triangles.size(); ++i) // exact boxes: the corners are doubles
        boxes.emplace_back(triangles[i][0].bbox() + triangles[i][1].bbox() + triangles[i][2].bbox(), i);
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(),
                                  [&](const Box& a, const Box& b) { pairs.emplace_back(a.info(), b.info()); });
    return pairs;
}

// The side of the plane of `t` that `p` lies on.
CGAL::Orientation sideOf(const InputCorners& t, const InputPoint& p)
{
    return CGAL::orientation(t[0], t[1], t[2], p);
}

// Two corners strictly on one side of a plane, or strictly on opposite sides.
bool oneSide(CGAL::Orientation x, CGAL::Orientation y)
{
    return x != CGAL::COPLANAR && x == y;
}
bool oppositeSides(CGAL::Orientation x, CGAL::Orientation y)
{
    return x != CGAL::COPLANAR && x == -y;
}

// Where the segment from p to q crosses the plane of `t` (p and q strictly on opposite
// sides), as lazy exact arithmetic: its interval approximation usually decides the
// predicates it feeds without rationals.
ExactPoint segmentCrossing(const ExactPoint& p, const ExactPoint& q, const Corners& t)
{
    const Plane3 plane(t[0], t[1], t[2]);
    const auto height = [&](const ExactPoint& x) {
        return plane.a() * x.x() + plane.b() * x.y() + plane.c() * x.z() + plane.d();
    };
    const FT hp = height(p);
    const FT along = hp / (hp - height(q));
    return p + (q - p) * along;
}

std::size_t next(std::size_t k, std::size_t step)
{
    return (k + step) % 3;
}

/// What the predicates on the input say of a pair whose boxes overlap.
struct PairContact {
    enum Kind : std::uint8_t {
        apart,        ///< they meet nowhere, or only at shared corners
        cornerCuts,   ///< they share corner a[i] = b[j] and each cuts the other's plane
        mayIntersect, ///< construct the intersection
    };
    Kind kind = apart;
    std::uint8_t i = 0, j = 0;
};

// Two triangles sharing the one corner v = a[i] = b[j] (most candidate pairs are
// neighbours in a mesh).
PairContact oneSharedCorner(const InputCorners& a, const InputCorners& b, std::size_t i, std::size_t j)
{
    const InputPoint& v = a[i];
    const InputPoint &a1 = a[next(i, 1)], &a2 = a[next(i, 2)], &b1 = b[next(j, 1)], &b2 = b[next(j, 2)];
    // Each corner's side of the other triangle's plane, decided once (most pairs).
    const CGAL::Orientation a1InB = sideOf(b, a1), a2InB = sideOf(b, a2);
    const CGAL::Orientation b1InA = sideOf(a, b1), b2InA = sideOf(a, b2);
    // a's other two corners strictly on one side of b's plane: a touches that plane only
    // at the shared corner (or the same the other way round).
    if (oneSide(a1InB, a2InB) || oneSide(b1InA, b2InA))
        return {};
    if (oppositeSides(a1InB, a2InB) && oppositeSides(b1InA, b2InA))
        return {PairContact::cornerCuts, std::uint8_t(i), std::uint8_t(j)};
    if (b1InA != CGAL::COPLANAR || b2InA != CGAL::COPLANAR)
        return {PairContact::mayIntersect};
    // In one plane (a fan in a flat region): the two corners at v are convex sectors,
    // which meet only at v iff a line along one of their four edges separates them.
    const auto beyond = [&](const InputPoint& edge, const InputPoint& own, const InputPoint& p, const InputPoint& q) {
        return CGAL::coplanar_orientation(v, edge, own, p) == CGAL::NEGATIVE &&
               CGAL::coplanar_orientation(v, edge, own, q) == CGAL::NEGATIVE;
    };
    if (beyond(a1, a2, b1, b2) || beyond(a2, a1, b1, b2) || beyond(b1, b2, a1, a2) || beyond(b2, b1, a1, a2))
        return {};
    return {PairContact::mayIntersect};
}

// Two triangles sharing an edge: the planes meet in its line, which each triangle meets
// in the edge alone; in one plane, the triangles meet only there when they lie on
// opposite sides of it. `third` is the corner of a off the edge, `bThird` b's.
PairContact sharedEdge(const InputCorners& a, const InputCorners& b, std::size_t third, std::size_t bThird)
{
    if (sideOf(a, b[bThird]) != CGAL::COPLANAR)
        return {};
    if (CGAL::coplanar_orientation(a[next(third, 1)], a[next(third, 2)], a[third], b[bThird]) == CGAL::NEGATIVE)
        return {};
    return {PairContact::mayIntersect};
}

// Decides with exact predicates on the input corners whether two triangles meet
// anywhere but at shared corners; allocation-free, so it runs on every candidate pair.
PairContact contactOf(const InputCorners& a, const InputCorners& b)
{
    constexpr std::size_t none = 3;
    std::array<std::size_t, 3> matchInB{none, none, none};
    int shared = 0;
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j)
            if (a[i] == b[j]) {
                matchInB[i] = j;
                ++shared;
            }
    if (shared == 1) {
        const std::size_t i = std::size_t(
            std::find_if(matchInB.begin(), matchInB.end(), [](std::size_t m) { return m != none; }) - matchInB.begin());
        return oneSharedCorner(a, b, i, matchInB[i]);
    }
    if (shared == 2) {
        const std::size_t i = std::size_t(std::find(matchInB.begin(), matchInB.end(), none) - matchInB.begin());
        std::size_t j = 0;
        while (j == matchInB[next(i, 1)] || j == matchInB[next(i, 2)])
            ++j;
        return sharedEdge(a, b, i, j);
    }
    if (shared == 3)
        return {PairContact::mayIntersect};
    // Apart when one triangle lies strictly on one side of the other's plane (most pairs
    // of a sliver's large box), else as the exact test of the two triangles says.
    const CGAL::Orientation b0 = sideOf(a, b[0]), b1 = sideOf(a, b[1]), b2 = sideOf(a, b[2]);
    if (oneSide(b0, b1) && b1 == b2)
        return {};
    const CGAL::Orientation a0 = sideOf(b, a[0]), a1 = sideOf(b, a[1]), a2 = sideOf(b, a[2]);
    if (oneSide(a0, a1) && a1 == a2)
        return {};
    const InputKernel::Triangle_3 ta(a[0], a[1], a[2]), tb(b[0], b[1], b[2]);
    return CGAL::do_intersect(ta, tb) ? PairContact{PairContact::mayIntersect} : PairContact{};
}

// For two triangles that share the corner v = a[i] = b[j] and each cut the other's
// plane: each meets the other's plane in a segment from v along the planes' common line,
// [v, p] and [v, q]. They share more than v only if p and q lie on the same side of v
// (the angle p v q is 0, not 180 degrees). Deciding this here keeps the exact
// intersection, which falls back to rationals at a shared corner, for the few pairs that
// really cross.
bool cutsMeetOnlyAtCorner(const Corners& a, const Corners& b, std::size_t i, std::size_t j)
{
    const ExactPoint p = segmentCrossing(a[next(i, 1)], a[next(i, 2)], b);
    const ExactPoint q = segmentCrossing(b[next(j, 1)], b[next(j, 2)], a);
    return CGAL::angle(p, a[i], q) == CGAL::OBTUSE;
}

// Where triangle `t` meets the plane of `other` (t's corners on its sides: `side`, not
// all on one side, not all in the plane): its corners in the plane and the crossings of
// its edges, one or two distinct points. Each crossing is one shallow construction from
// the input doubles, so the rare predicate that must evaluate it exactly stays cheap.
std::vector<ExactPoint> meetingWithPlane(const Corners& t, const std::array<CGAL::Orientation, 3>& side,
                                         const Corners& other)
{
    std::vector<ExactPoint> points;
    for (std::size_t k = 0; k < 3; ++k) {
        if (side[k] == CGAL::COPLANAR)
            points.push_back(t[k]);
        else if (oppositeSides(side[k], side[next(k, 1)]))
            points.push_back(segmentCrossing(t[k], t[next(k, 1)], other));
    }
    return points;
}

// The ends of a run of points on one line, by the lexicographic order (monotone along
// any line).
std::array<ExactPoint, 2> ends(const std::vector<ExactPoint>& points)
{
    const auto less = [](const ExactPoint& p, const ExactPoint& q) { return CGAL::compare_xyz(p, q) == CGAL::SMALLER; };
    return {*std::min_element(points.begin(), points.end(), less),
            *std::max_element(points.begin(), points.end(), less)};
}

// Records what triangles i and j leave on each other; those that overlap in their
// common plane become one group (triangulated together). Two triangles in different
// planes meet where the parts of each in the other's plane overlap on the planes' common
// line: a point or a segment.
void markIntersection(std::size_t i, std::size_t j, const std::vector<Corners>& triangles,
                      const std::vector<InputCorners>& input, std::vector<Marks>& marks, UnionFind& groups)
{
    std::array<CGAL::Orientation, 3> iInJ{}, jInI{};
    for (std::size_t k = 0; k < 3; ++k) {
        iInJ[k] = sideOf(input[j], input[i][k]);
        jInI[k] = sideOf(input[i], input[j][k]);
    }
    const auto allIn = [](const std::array<CGAL::Orientation, 3>& side) {
        return std::all_of(side.begin(), side.end(), [](CGAL::Orientation o) { return o == CGAL::COPLANAR; });
    };
    const auto allOneSide = [](const std::array<CGAL::Orientation, 3>& side) {
        return oneSide(side[0], side[1]) && side[1] == side[2];
    };
    if (allOneSide(iInJ) || allOneSide(jInI))
        return;
    if (allIn(iInJ)) {
        const Triangle3 a(triangles[i][0], triangles[i][1], triangles[i][2]);
        const Triangle3 b(triangles[j][0], triangles[j][1], triangles[j][2]);
        const auto meeting = CGAL::intersection(a, b);
        if (!meeting)
            return;
        if (const ExactPoint* point = boost::get<ExactPoint>(&*meeting)) {
            marks[i].points.push_back(*point);
            marks[j].points.push_back(*point);
        } else if (const Segment3* segment = boost::get<Segment3>(&*meeting)) {
            marks[i].segments.push_back({segment->source(), segment->target()});
            marks[j].segments.push_back({segment->source(), segment->target()});
        } else {
            groups.unite(i, j); // a triangle or polygon: they overlap in one plane
        }
        return;
    }
    const std::array<ExactPoint, 2> a = ends(meetingWithPlane(triangles[i], iInJ, triangles[j]));
    const std::array<ExactPoint, 2> b = ends(meetingWithPlane(triangles[j], jInI, triangles[i]));
    const ExactPoint& low = CGAL::compare_xyz(a[0], b[0]) == CGAL::LARGER ? a[0] : b[0];
    const ExactPoint& high = CGAL::compare_xyz(a[1], b[1]) == CGAL::SMALLER ? a[1] : b[1];
    const CGAL::Comparison_result order = CGAL::compare_xyz(low, high);
    if (order == CGAL::LARGER)
        return;
    if (order == CGAL::EQUAL) {
        marks[i].points.push_back(low);
        marks[j].points.push_back(low);
    } else {
        marks[i].segments.push_back({low, high});
        marks[j].segments.push_back({low, high});
    }
}

// The coordinate axis along which the plane projects best (the normal's largest
// component): the projection onto the other two is one-to-one on the plane.
int dominantAxis(const ExactVector& normal)
{
    int axis = 0;
    for (int k = 1; k < 3; ++k)
        if (CGAL::compare(CGAL::abs(normal[k]), CGAL::abs(normal[axis])) == CGAL::LARGER)
            axis = k;
    return axis;
}

// Drops coordinate `axis`, keeping the other two in cyclic order (so a triangle
// projects counter-clockwise when its normal points along +axis).
struct Projection {
    const Plane3& plane;
    int axis = 0;

    [[nodiscard]] Point2 operator()(const ExactPoint& p) const { return {p[(axis + 1) % 3], p[(axis + 2) % 3]}; }

    /// The point of the plane that projects to `q`.
    [[nodiscard]] ExactPoint lift(const Point2& q) const
    {
        const std::array<FT, 3> n{plane.a(), plane.b(), plane.c()};
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        std::array<FT, 3> xyz;
        xyz[std::size_t(u)] = q.x();
        xyz[std::size_t(v)] = q.y();
        xyz[std::size_t(axis)] =
            -(n[std::size_t(u)] * q.x() + n[std::size_t(v)] * q.y() + plane.d()) / n[std::size_t(axis)];
        return {xyz[0], xyz[1], xyz[2]};
    }
};

// Triangulates one group (coplanar triangles that overlap, or a lone triangle) with
// every member's edges and marks as constraints, and gives each piece to every member
// that covers it, in that member's orientation.
void triangulateGroup(const std::vector<std::size_t>& members, const std::vector<Corners>& triangles,
                      const std::vector<Marks>& marks, std::vector<ArrangedTriangle>& pieces)
{
    const Corners& first = triangles[members.front()];
    const Plane3 plane(first[0], first[1], first[2]);
    const Projection project{plane, dominantAxis(plane.orthogonal_vector())};
    PlaneTriangulation triangulation;
    const auto vertexAt = [&](const ExactPoint& p) {
        const PlaneTriangulation::Vertex_handle v = triangulation.insert(project(p));
        if (!v->info())
            v->info() = p;
        return v;
    };
    const auto constrain = [&](const ExactPoint& p, const ExactPoint& q) {
        const PlaneTriangulation::Vertex_handle vp = vertexAt(p), vq = vertexAt(q);
        if (vp != vq)
            triangulation.insert_constraint(vp, vq);
    };
    for (std::size_t m : members) {
        const Corners& t = triangles[m];
        for (std::size_t k = 0; k < 3; ++k)
            constrain(t[k], t[(k + 1) % 3]);
        for (const ExactPoint& p : marks[m].points)
            vertexAt(p);
        for (const auto& s : marks[m].segments)
            constrain(s[0], s[1]);
    }
    for (auto v = triangulation.finite_vertices_begin(); v != triangulation.finite_vertices_end(); ++v)
        if (!v->info())
            v->info() = project.lift(v->point()); // where two constraints cross

    std::vector<Triangle2> shadows;
    std::vector<bool> clockwise; ///< per member: its shadow runs clockwise (the pieces run counter-clockwise)
    for (std::size_t m : members) {
        shadows.emplace_back(project(triangles[m][0]), project(triangles[m][1]), project(triangles[m][2]));
        clockwise.push_back(shadows.back().orientation() == CGAL::CLOCKWISE);
    }
    for (auto f = triangulation.finite_faces_begin(); f != triangulation.finite_faces_end(); ++f) {
        const std::array<ExactPoint, 3> corners{*f->vertex(0)->info(), *f->vertex(1)->info(), *f->vertex(2)->info()};
        // Every member's edges are constraints, so a piece is inside a member or outside
        // it entirely; its centroid decides. A lone triangle is the hull of its points.
        const Point2 centre = CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
        for (std::size_t k = 0; k < members.size(); ++k) {
            if (members.size() > 1 && !shadows[k].has_on_bounded_side(centre))
                continue;
            ArrangedTriangle piece{corners, members[k]};
            if (clockwise[k])
                std::swap(piece.corners[1], piece.corners[2]);
            pieces.push_back(std::move(piece));
        }
    }
}

// The doubles the exact corners were made from (refineScene makes them so).
std::vector<InputCorners> inputCorners(const std::vector<Corners>& triangles)
{
    std::vector<InputCorners> input;
    input.reserve(triangles.size());
    const auto exactDouble = [](const FT& x) {
        if (!x.approx().is_point())
            throw std::invalid_argument("the arrangement's input corners must be doubles");
        return x.approx().inf();
    };
    for (const Corners& t : triangles) {
        InputCorners& c = input.emplace_back();
        for (std::size_t k = 0; k < 3; ++k)
            c[k] = InputPoint(exactDouble(t[k].x()), exactDouble(t[k].y()), exactDouble(t[k].z()));
    }
    return input;
}

// Runs body(k) for k in [0, count) on every core, in chunks so that handing out an item
// costs nothing next to the work; cancellation as parallelFor.
void runInChunks(std::size_t count, const TaskControl& control, const std::function<void(std::size_t)>& body)
{
    constexpr std::size_t kChunks = 64;
    const std::size_t chunk = std::max<std::size_t>(1, (count + kChunks - 1) / kChunks);
    const TaskControl quiet{{}, control.stop}; // the caller reports the stage
    parallelFor((count + chunk - 1) / chunk, 0,
                [&](std::size_t c) {
                    for (std::size_t k = c * chunk; k < std::min(count, (c + 1) * chunk); ++k)
                        body(k);
                },
                quiet);
}

struct CandidatePair {
    std::size_t index = 0; ///< into the candidate pairs
    PairContact contact;
};

std::vector<CandidatePair> undecidedPairs(const std::vector<std::pair<std::size_t, std::size_t>>& pairs,
                                          const std::vector<InputCorners>& input, const TaskControl& control)
{
    constexpr std::size_t kChunks = 256;
    const std::size_t chunk = std::max<std::size_t>(1, (pairs.size() + kChunks - 1) / kChunks);
    std::vector<std::vector<CandidatePair>> found((pairs.size() + chunk - 1) / chunk);
    const TaskControl quiet{{}, control.stop};
    parallelFor(
        found.size(), 0,
        [&](std::size_t c) {
            for (std::size_t p = c * chunk; p < std::min(pairs.size(), (c + 1) * chunk); ++p) {
                const PairContact contact = contactOf(input[pairs[p].first], input[pairs[p].second]);
                if (contact.kind != PairContact::apart)
                    found[c].push_back({p, contact});
            }
        },
        quiet);
    std::vector<CandidatePair> all;
    for (const std::vector<CandidatePair>& part : found)
        all.insert(all.end(), part.begin(), part.end());
    return all;
}

} // namespace

std::vector<ArrangedTriangle> arrangeTriangles(const std::vector<std::array<ExactPoint, 3>>& triangles,
                                               const TaskControl& control, ExactProfile* profile)
{
    ExactProfile local;
    ExactProfile& measured = profile != nullptr ? *profile : local;
    auto start = std::chrono::steady_clock::now();
    const auto lap = [&start](double& ms) {
        const auto now = std::chrono::steady_clock::now();
        ms += std::chrono::duration<double, std::milli>(now - start).count();
        start = now;
    };
    const std::vector<InputCorners> input = inputCorners(triangles);
    const auto pairs = overlappingBoxes(triangles);
    measured.candidatePairs += pairs.size();
    lap(measured.boxesMs);

    // The pairs the input's predicates cannot clear, in the order of `pairs` whatever
    // the thread count (the arrangement does not depend on it).
    const std::vector<CandidatePair> crossing = undecidedPairs(pairs, input, control);
    lap(measured.pairsMs);
    std::vector<Marks> marks(triangles.size());
    UnionFind groups(triangles.size());
    constexpr std::size_t kCheckEvery = 4096;
    for (std::size_t p = 0; p < crossing.size(); ++p) {
        if (p % kCheckEvery == 0)
            control.throwIfCancelled();
        const CandidatePair& pair = crossing[p];
        const std::size_t i = pairs[pair.index].first, j = pairs[pair.index].second;
        if (pair.contact.kind == PairContact::cornerCuts &&
            cutsMeetOnlyAtCorner(triangles[i], triangles[j], pair.contact.i, pair.contact.j))
            continue;
        ++measured.constructedPairs;
        markIntersection(i, j, triangles, input, marks, groups);
    }
    lap(measured.constructMs);

    std::vector<std::vector<std::size_t>> members(triangles.size());
    for (std::size_t i = 0; i < triangles.size(); ++i)
        members[groups.find(i)].push_back(i);
    std::vector<std::size_t> split; ///< the roots of groups to triangulate
    for (std::size_t root = 0; root < triangles.size(); ++root) {
        const std::size_t size = members[root].size();
        if (size > 1) {
            ++measured.coplanarGroups;
            measured.largestCoplanarGroup = std::max(measured.largestCoplanarGroup, size);
        }
        if (size > 1 || (size == 1 && (!marks[root].points.empty() || !marks[root].segments.empty()))) {
            split.push_back(root);
            measured.splitTriangles += size;
        }
    }
    std::vector<std::vector<ArrangedTriangle>> splitPieces(split.size());
    runInChunks(split.size(), control,
                [&](std::size_t k) { triangulateGroup(members[split[k]], triangles, marks, splitPieces[k]); });
    std::vector<ArrangedTriangle> pieces;
    pieces.reserve(triangles.size() + split.size());
    std::size_t nextSplit = 0;
    for (std::size_t root = 0; root < triangles.size(); ++root) {
        if (nextSplit < split.size() && split[nextSplit] == root) {
            std::move(splitPieces[nextSplit].begin(), splitPieces[nextSplit].end(), std::back_inserter(pieces));
            ++nextSplit;
        } else if (members[root].size() == 1) {
            pieces.push_back({triangles[root], root});
        }
    }
    lap(measured.triangulateMs);
    return pieces;
}

} // namespace trimlab::solid
