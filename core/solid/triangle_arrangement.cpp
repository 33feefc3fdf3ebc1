#include "core/solid/triangle_arrangement.h"

#include "core/util/parallel_for.h"
#include "core/util/union_find.h"

#include <CGAL/Constrained_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <cmath>
#include <chrono>
#include <functional>
#include <iterator>
#include <limits>
#include <optional>
#include <stdexcept>
#include <unordered_map>
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

/// A point another triangle leaves on a triangle, and where on that triangle it lies when
/// the construction tells without a predicate: inside its edge from corner `edge` to the
/// next, or (kAnywhere) wherever point location finds it.
constexpr std::uint8_t kAnywhere = 3;

struct MarkPoint {
    ExactPoint point;
    std::uint8_t edge = kAnywhere;
};

/// What other triangles leave on a triangle: points where they touch it, segments where
/// they cross it.
struct Marks {
    std::vector<MarkPoint> points;
    std::vector<std::array<MarkPoint, 2>> segments;
};

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

// The crossings of input edges with other triangles' planes, one exact point per edge
// and plane however many triangles share the edge: a point reached from the triangles on
// both sides of an edge and from the triangle it crosses is then one handle, which the
// triangulations and the merge recognise by identity instead of evaluating it exactly.
class EdgeCrossings {
public:
    /// Where the edge from corner k to corner k + 1 of triangle t crosses the plane of
    /// triangle `other` (its ends strictly on opposite sides).
    const ExactPoint& crossing(const Corners& t, const InputCorners& input, std::size_t k, const Corners& plane,
                               std::size_t other)
    {
        std::size_t from = k, to = next(k, 1);
        if (CGAL::compare_xyz(input[from], input[to]) == CGAL::LARGER)
            std::swap(from, to);
        const InputPoint &p = input[from], &q = input[to];
        const Key key{p.x(), p.y(), p.z(), q.x(), q.y(), q.z(), double(other)};
        const auto found = known_.find(key);
        if (found != known_.end())
            return found->second;
        return known_.emplace(key, segmentCrossing(t[from], t[to], plane)).first->second;
    }

private:
    using Key = std::array<double, 7>; ///< the edge's ends in lexicographic order, the plane's triangle
    struct KeyHash {
        std::size_t operator()(const Key& key) const
        {
            std::size_t h = 0;
            for (double x : key)
                h = h * 1000003u ^ std::hash<double>{}(x);
            return h;
        }
    };
    std::unordered_map<Key, ExactPoint, KeyHash> known_;
};

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

// Where triangle i meets the plane of triangle j (i's corners on its sides: `side`, not
// all on one side, not all in the plane): its corners in the plane and the crossings of
// its edges, one or two distinct points, each tagged with the edge of i it lies in. Each
// crossing is one shallow construction from the input doubles, so the rare predicate
// that must evaluate it exactly stays cheap.
std::vector<MarkPoint> meetingWithPlane(std::size_t i, const std::array<CGAL::Orientation, 3>& side, std::size_t j,
                                        const std::vector<Corners>& triangles, const std::vector<InputCorners>& input,
                                        EdgeCrossings& crossings)
{
    std::vector<MarkPoint> points;
    for (std::size_t k = 0; k < 3; ++k) {
        if (side[k] == CGAL::COPLANAR)
            points.push_back({triangles[i][k]}); // a corner: its own handle
        else if (oppositeSides(side[k], side[next(k, 1)]))
            points.push_back({crossings.crossing(triangles[i], input[i], k, triangles[j], j), std::uint8_t(k)});
    }
    return points;
}

// The ends of a run of points on one line, by the lexicographic order (monotone along
// any line).
std::array<MarkPoint, 2> ends(const std::vector<MarkPoint>& points)
{
    const auto less = [](const MarkPoint& p, const MarkPoint& q) {
        return !CGAL::identical(p.point, q.point) && CGAL::compare_xyz(p.point, q.point) == CGAL::SMALLER;
    };
    return {*std::min_element(points.begin(), points.end(), less),
            *std::max_element(points.begin(), points.end(), less)};
}

// `point` as a mark of the triangle whose meeting with the other's plane it came from
// (`own`: its edge is known), or of the other triangle (anywhere in it).
MarkPoint markOf(const MarkPoint& point, bool own)
{
    return own ? point : MarkPoint{point.point};
}

// Records what triangles i and j leave on each other; those that overlap in their
// common plane become one group (triangulated together). Two triangles in different
// planes meet where the parts of each in the other's plane overlap on the planes' common
// line: a point or a segment.
void markIntersection(std::size_t i, std::size_t j, const std::vector<Corners>& triangles,
                      const std::vector<InputCorners>& input, EdgeCrossings& crossings, std::vector<Marks>& marks,
                      UnionFind& groups)
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
            marks[i].points.push_back({*point});
            marks[j].points.push_back({*point});
        } else if (const Segment3* segment = boost::get<Segment3>(&*meeting)) {
            const std::array<MarkPoint, 2> ends{MarkPoint{segment->source()}, MarkPoint{segment->target()}};
            marks[i].segments.push_back(ends);
            marks[j].segments.push_back(ends);
        } else {
            groups.unite(i, j); // a triangle or polygon: they overlap in one plane
        }
        return;
    }
    const std::array<MarkPoint, 2> a = ends(meetingWithPlane(i, iInJ, j, triangles, input, crossings));
    const std::array<MarkPoint, 2> b = ends(meetingWithPlane(j, jInI, i, triangles, input, crossings));
    const bool lowOfI = CGAL::compare_xyz(a[0].point, b[0].point) == CGAL::LARGER;
    const bool highOfI = CGAL::compare_xyz(a[1].point, b[1].point) == CGAL::SMALLER;
    const MarkPoint& low = lowOfI ? a[0] : b[0];
    const MarkPoint& high = highOfI ? a[1] : b[1];
    const CGAL::Comparison_result order =
        CGAL::identical(low.point, high.point) ? CGAL::EQUAL : CGAL::compare_xyz(low.point, high.point);
    if (order == CGAL::LARGER)
        return;
    if (order == CGAL::EQUAL) {
        marks[i].points.push_back(markOf(low, lowOfI));
        marks[j].points.push_back(markOf(low, !lowOfI));
    } else {
        marks[i].segments.push_back({markOf(low, lowOfI), markOf(high, highOfI)});
        marks[j].segments.push_back({markOf(low, !lowOfI), markOf(high, !highOfI)});
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

using VertexHandle = PlaneTriangulation::Vertex_handle;

// The triangulation of one group in its plane, its vertices found by the handle of the
// exact point they were made for: a point reached again through the same handle (a
// segment's end shared with the next segment, a corner) needs no point location, which
// would evaluate it exactly to find it equal.
struct GroupTriangulation {
    PlaneTriangulation triangulation;
    Projection project;
    std::unordered_map<CGAL::Handle::Id_type, VertexHandle> byHandle;

    VertexHandle vertexAt(const ExactPoint& p)
    {
        const auto found = byHandle.find(p.id());
        if (found != byHandle.end())
            return found->second;
        const VertexHandle v = triangulation.insert(project(p));
        if (!v->info())
            v->info() = p;
        byHandle.emplace(p.id(), v);
        return v;
    }

    void constrain(VertexHandle a, VertexHandle b)
    {
        if (a != b)
            triangulation.insert_constraint(a, b);
    }

    // Inserts `points`, all inside the edge of a lone triangle from corner `fromPoint`
    // (vertex `from`) to `toPoint` (vertex `to`), the triangulation's hull edge, in their order along it, each into the
    // piece of the edge it splits: no predicate but that order, where point location
    // would find each exactly on the edge (a predicate that is exactly zero, evaluated in
    // rationals).
    void insertAlongEdge(std::vector<const ExactPoint*> points, const ExactPoint& fromPoint, const ExactPoint& toPoint,
                         VertexHandle from, VertexHandle to)
    {
        const auto distinctHandle = [](const ExactPoint* p, const ExactPoint* q) { return p->id() < q->id(); };
        std::sort(points.begin(), points.end(), distinctHandle);
        points.erase(std::unique(points.begin(), points.end(),
                                 [](const ExactPoint* p, const ExactPoint* q) { return p->id() == q->id(); }),
                     points.end());
        // Lexicographic order is monotone along the edge: nearer `fromPoint` first.
        const CGAL::Comparison_result nearerFirst = CGAL::compare_xyz(fromPoint, toPoint);
        std::sort(points.begin(), points.end(),
                  [&](const ExactPoint* p, const ExactPoint* q) { return CGAL::compare_xyz(*p, *q) == nearerFirst; });
        VertexHandle previous = from;
        const ExactPoint* last = nullptr;
        for (const ExactPoint* p : points) {
            if (last != nullptr && CGAL::compare_xyz(*last, *p) == CGAL::EQUAL) {
                byHandle.emplace(p->id(), previous); // equal points made twice
                continue;
            }
            PlaneTriangulation::Face_handle face;
            int index = 0;
            if (!triangulation.is_edge(previous, to, face, index))
                throw std::logic_error("arrangement: a point on a triangle's edge lost its edge");
            const VertexHandle v = triangulation.insert(project(*p), PlaneTriangulation::EDGE, face, index);
            v->info() = *p;
            byHandle.emplace(p->id(), v);
            previous = v;
            last = p;
        }
    }
};

// A lone triangle with what others leave on it: its corners, the marks known to lie in
// each edge along that edge, the rest by point location, and the segments as constraints
// (its edges are the triangulation's hull, so they need none).
void triangulateLone(GroupTriangulation& group, const Corners& t, const Marks& marks)
{
    std::array<VertexHandle, 3> corner;
    for (std::size_t k = 0; k < 3; ++k)
        corner[k] = group.vertexAt(t[k]);
    std::array<std::vector<const ExactPoint*>, 3> onEdge;
    const auto collect = [&](const MarkPoint& m) {
        if (m.edge != kAnywhere)
            onEdge[m.edge].push_back(&m.point);
    };
    for (const MarkPoint& m : marks.points)
        collect(m);
    for (const auto& segment : marks.segments) {
        collect(segment[0]);
        collect(segment[1]);
    }
    for (std::size_t k = 0; k < 3; ++k)
        group.insertAlongEdge(std::move(onEdge[k]), t[k], t[next(k, 1)], corner[k], corner[next(k, 1)]);
    for (const MarkPoint& m : marks.points)
        group.vertexAt(m.point);
    for (const auto& segment : marks.segments)
        group.constrain(group.vertexAt(segment[0].point), group.vertexAt(segment[1].point));
}

// The pieces of one group by source, then by their corners in lexicographic order, each
// starting at its smallest corner (its orientation kept). A triangulation lists its faces
// and their corners in an order that depends on its history, and with the groups
// triangulated on two cores over shared, lazily evaluated points that order was seen to
// change from run to run on a loaded machine (the same pieces, listed differently); in
// this order the refined mesh, and the file written from it, is the same on every run.
void inCanonicalOrder(std::vector<ArrangedTriangle>& pieces)
{
    const auto less = [](const ExactPoint& a, const ExactPoint& b) { return CGAL::compare_xyz(a, b) == CGAL::SMALLER; };
    for (ArrangedTriangle& piece : pieces) {
        auto& c = piece.corners;
        const std::size_t smallest = less(c[1], c[0]) ? (less(c[2], c[1]) ? 2 : 1) : (less(c[2], c[0]) ? 2 : 0);
        std::rotate(c.begin(), c.begin() + std::ptrdiff_t(smallest), c.end());
    }
    std::sort(pieces.begin(), pieces.end(), [&](const ArrangedTriangle& a, const ArrangedTriangle& b) {
        if (a.source != b.source)
            return a.source < b.source;
        for (std::size_t k = 0; k < 3; ++k) {
            const CGAL::Comparison_result order = CGAL::compare_xyz(a.corners[k], b.corners[k]);
            if (order != CGAL::EQUAL)
                return order == CGAL::SMALLER;
        }
        return false;
    });
}

// Triangulates one group (coplanar triangles that overlap, or a lone triangle) with
// every member's edges and marks as constraints, and gives each piece to every member
// that covers it, in that member's orientation.
void triangulateGroup(const std::vector<std::size_t>& members, const std::vector<Corners>& triangles,
                      const std::vector<Marks>& marks, std::vector<ArrangedTriangle>& pieces)
{
    const Corners& first = triangles[members.front()];
    const Plane3 plane(first[0], first[1], first[2]);
    GroupTriangulation group{{}, Projection{plane, dominantAxis(plane.orthogonal_vector())}, {}};
    PlaneTriangulation& triangulation = group.triangulation;
    const Projection& project = group.project;
    if (members.size() == 1) {
        triangulateLone(group, first, marks[members.front()]);
    } else {
        for (std::size_t m : members) {
            const Corners& t = triangles[m];
            for (std::size_t k = 0; k < 3; ++k)
                group.constrain(group.vertexAt(t[k]), group.vertexAt(t[(k + 1) % 3]));
            for (const MarkPoint& p : marks[m].points)
                group.vertexAt(p.point);
            for (const auto& segment : marks[m].segments)
                group.constrain(group.vertexAt(segment[0].point), group.vertexAt(segment[1].point));
        }
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
    std::size_t first = 0, second = 0; ///< first < second
    PairContact contact;
};

/// The pairs one slab of space found, and how many pairs of triangles' boxes it saw.
struct SlabPairs {
    std::vector<CandidatePair> undecided;
    std::size_t overlapping = 0;
};

// A triangle lying obliquely to the axes and much longer than the scene's typical one
// also gets boxes of its parts, cut across the longest axis of its box: such a sliver's
// one box holds mostly empty space and meets thousands of others' (most candidate pairs
// of CAD parts), its parts' boxes far fewer. A pair of triangles whose boxes overlap but
// whose parts' boxes do not is apart, with no predicate. One along an axis fills its box
// already.
constexpr std::size_t kMaxParts = 4;

/// The boxes of every triangle's parts (one part: its own box).
struct PartBoxes {
    std::vector<CGAL::Bbox_3> whole; ///< per triangle
    std::vector<CGAL::Bbox_3> boxes;
    std::vector<std::size_t> first; ///< boxes[first[i]] .. boxes[first[i + 1]]: triangle i's parts

    [[nodiscard]] const CGAL::Bbox_3& part(std::size_t triangle, std::size_t k) const
    {
        return boxes[first[triangle] + k];
    }
    [[nodiscard]] std::size_t parts(std::size_t triangle) const { return first[triangle + 1] - first[triangle]; }
};

// The box of the part of triangle t between a = low and a = high along axis a, grown
// across the other axes by a margin far above the rounding of the crossings of its edges
// with those two planes: a filter must never lose a pair.
CGAL::Bbox_3 partBox(const InputCorners& t, int a, double low, double high)
{
    std::array<double, 3> min{}, max{};
    min.fill(std::numeric_limits<double>::infinity());
    max.fill(-std::numeric_limits<double>::infinity());
    double magnitude = 0.0;
    const auto include = [&](const std::array<double, 3>& p) {
        for (std::size_t k = 0; k < 3; ++k) {
            min[k] = std::min(min[k], p[k]);
            max[k] = std::max(max[k], p[k]);
        }
    };
    for (std::size_t k = 0; k < 3; ++k) {
        const InputPoint& p = t[k];
        const InputPoint& q = t[next(k, 1)];
        for (int d = 0; d < 3; ++d)
            magnitude = std::max(magnitude, std::abs(p[d]));
        if (p[a] >= low && p[a] <= high)
            include({p.x(), p.y(), p.z()});
        for (double plane : {low, high}) {
            if (p[a] == q[a] || plane < std::min(p[a], q[a]) || plane > std::max(p[a], q[a]))
                continue;
            const double along = (plane - p[a]) / (q[a] - p[a]);
            include(
                {p.x() + along * (q.x() - p.x()), p.y() + along * (q.y() - p.y()), p.z() + along * (q.z() - p.z())});
        }
    }
    const double margin = 64.0 * std::numeric_limits<double>::epsilon() * magnitude;
    for (int d = 0; d < 3; ++d) {
        if (d == a) {
            min[std::size_t(d)] = low;
            max[std::size_t(d)] = high;
        } else {
            min[std::size_t(d)] -= margin;
            max[std::size_t(d)] += margin;
        }
    }
    return {min[0], min[1], min[2], max[0], max[1], max[2]};
}

int longestAxis(const CGAL::Bbox_3& b)
{
    int a = 0;
    for (int d = 1; d < 3; ++d)
        if (b.max(d) - b.min(d) > b.max(a) - b.min(a))
            a = d;
    return a;
}

// How many parts triangle t is boxed in: as many as its box's face across its two
// longest axes is larger than the triangle's shadow on it (about 2 when it lies along an
// axis), and no more than it is longer than the typical triangle (`length`), up to
// kMaxParts. A heuristic for speed only: any count covers the triangle.
std::size_t partCount(const InputCorners& t, const CGAL::Bbox_3& b, double length)
{
    if (length < 2.0)
        return 1;
    std::array<double, 3> extent{b.xmax() - b.xmin(), b.ymax() - b.ymin(), b.zmax() - b.zmin()};
    const std::size_t thinnest = std::size_t(std::min_element(extent.begin(), extent.end()) - extent.begin());
    const std::size_t u = (thinnest + 1) % 3, v = (thinnest + 2) % 3;
    const std::array<double, 3> e1{t[1].x() - t[0].x(), t[1].y() - t[0].y(), t[1].z() - t[0].z()};
    const std::array<double, 3> e2{t[2].x() - t[0].x(), t[2].y() - t[0].y(), t[2].z() - t[0].z()};
    const double shadow = 0.5 * std::abs(e1[u] * e2[v] - e1[v] * e2[u]);
    const double emptiness = shadow > 0.0 ? extent[u] * extent[v] / shadow : double(kMaxParts) * 4.0;
    return std::size_t(std::clamp(std::floor(std::min(emptiness / 64.0, length)), 1.0, double(kMaxParts)));
}

PartBoxes partBoxes(const std::vector<InputCorners>& input)
{
    PartBoxes result;
    std::vector<CGAL::Bbox_3>& whole = result.whole;
    whole.reserve(input.size());
    std::vector<double> longest;
    longest.reserve(input.size());
    for (const InputCorners& t : input) { // exact boxes: the corners are doubles
        whole.push_back(t[0].bbox() + t[1].bbox() + t[2].bbox());
        const CGAL::Bbox_3& b = whole.back();
        longest.push_back(std::max({b.xmax() - b.xmin(), b.ymax() - b.ymin(), b.zmax() - b.zmin()}));
    }
    std::vector<double> sorted = longest;
    const auto middle = sorted.begin() + std::ptrdiff_t(sorted.size() / 2);
    std::nth_element(sorted.begin(), middle, sorted.end());
    const double typical = sorted.empty() ? 0.0 : *middle;

    result.first.reserve(input.size() + 1);
    for (std::size_t i = 0; i < input.size(); ++i) {
        result.first.push_back(result.boxes.size());
        const CGAL::Bbox_3& b = whole[i];
        const std::size_t parts = typical > 0.0 ? partCount(input[i], b, longest[i] / typical) : 1;
        if (parts == 1) {
            result.boxes.push_back(b);
            continue;
        }
        const int a = longestAxis(b);
        // Shared cut positions, and the box's own ends at either end: the parts' extents
        // along the axis tile the box's exactly.
        for (std::size_t k = 0; k < parts; ++k) {
            const double low = k == 0 ? b.min(a) : b.min(a) + (b.max(a) - b.min(a)) * double(k) / double(parts);
            const double high =
                k + 1 == parts ? b.max(a) : b.min(a) + (b.max(a) - b.min(a)) * double(k + 1) / double(parts);
            result.boxes.push_back(partBox(input[i], a, low, high));
        }
    }
    result.first.push_back(result.boxes.size());
    return result;
}

// Whether any part of triangle i has a box that overlaps one of triangle j's.
bool partsMeet(const PartBoxes& boxes, std::size_t i, std::size_t j)
{
    for (std::size_t s = 0; s < boxes.parts(i); ++s)
        for (std::size_t t = 0; t < boxes.parts(j); ++t)
            if (CGAL::do_overlap(boxes.part(i, s), boxes.part(j, t)))
                return true;
    return false;
}

// Slabs of space across the longest axis of the scene, a fixed number whatever the core
// count (the pairs' order, and so the arrangement, does not depend on it), their
// boundaries at quantiles of the boxes' lower ends so that each starts as many boxes.
constexpr std::size_t kSlabs = 16;

struct Slabs {
    int axis = 0;
    std::array<double, kSlabs - 1> boundaries{};

    /// The slab holding coordinate x along the axis.
    [[nodiscard]] std::size_t of(double x) const
    {
        return std::size_t(std::upper_bound(boundaries.begin(), boundaries.end(), x) - boundaries.begin());
    }
};

Slabs slabsOf(const std::vector<Box>& boxes)
{
    std::array<double, 3> low{}, high{};
    low.fill(std::numeric_limits<double>::infinity());
    high.fill(-std::numeric_limits<double>::infinity());
    for (const Box& box : boxes)
        for (int k = 0; k < 3; ++k) {
            low[std::size_t(k)] = std::min(low[std::size_t(k)], box.min_coord(k));
            high[std::size_t(k)] = std::max(high[std::size_t(k)], box.max_coord(k));
        }
    Slabs slabs;
    for (int k = 1; k < 3; ++k)
        if (high[std::size_t(k)] - low[std::size_t(k)] > high[std::size_t(slabs.axis)] - low[std::size_t(slabs.axis)])
            slabs.axis = k;
    std::vector<double> lower;
    lower.reserve(boxes.size());
    for (const Box& box : boxes)
        lower.push_back(box.min_coord(slabs.axis));
    std::sort(lower.begin(), lower.end());
    for (std::size_t s = 1; s < kSlabs; ++s)
        slabs.boundaries[s - 1] = lower.empty() ? 0.0 : lower[lower.size() * s / kSlabs];
    return slabs;
}

// The pairs of triangles whose boxes (and their parts' boxes) overlap and that the
// input's predicates cannot clear, each decided as the box intersection finds it (pairs
// of boxes run to millions; none is stored unless undecided). Every slab runs on its own
// core with the boxes that reach into it, and keeps the pairs of boxes whose overlap
// begins in it along the axis (the larger of the two lower ends): each pair once.
std::vector<CandidatePair> undecidedPairs(const std::vector<InputCorners>& input, const TaskControl& control,
                                          std::size_t& overlapping)
{
    const PartBoxes parts = partBoxes(input);
    std::vector<Box> boxes;
    boxes.reserve(input.size());
    for (std::size_t i = 0; i < input.size(); ++i)
        boxes.emplace_back(parts.whole[i], i);
    const Slabs slabs = slabsOf(boxes);
    std::vector<SlabPairs> found(kSlabs);
    const TaskControl quiet{{}, control.stop}; // the caller reports the stage
    parallelFor(
        kSlabs, 0,
        [&](std::size_t slab) {
            std::vector<Box> reaching;
            for (const Box& box : boxes)
                if (slabs.of(box.min_coord(slabs.axis)) <= slab && slab <= slabs.of(box.max_coord(slabs.axis)))
                    reaching.push_back(box);
            SlabPairs& pairs = found[slab];
            CGAL::box_self_intersection_d(reaching.begin(), reaching.end(), [&](const Box& a, const Box& b) {
                if (slabs.of(std::max(a.min_coord(slabs.axis), b.min_coord(slabs.axis))) != slab)
                    return;
                const std::size_t i = std::min(a.info(), b.info()), j = std::max(a.info(), b.info());
                if ((parts.parts(i) > 1 || parts.parts(j) > 1) && !partsMeet(parts, i, j))
                    return;
                ++pairs.overlapping;
                const PairContact contact = contactOf(input[i], input[j]);
                if (contact.kind != PairContact::apart)
                    pairs.undecided.push_back({i, j, contact});
            });
        },
        quiet);
    std::vector<CandidatePair> all;
    for (const SlabPairs& pairs : found) {
        overlapping += pairs.overlapping;
        all.insert(all.end(), pairs.undecided.begin(), pairs.undecided.end());
    }
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
    const std::vector<CandidatePair> crossing = undecidedPairs(input, control, measured.candidatePairs);
    lap(measured.pairsMs);
    std::vector<Marks> marks(triangles.size());
    UnionFind groups(triangles.size());
    EdgeCrossings crossings;
    constexpr std::size_t kCheckEvery = 4096;
    for (std::size_t p = 0; p < crossing.size(); ++p) {
        if (p % kCheckEvery == 0)
            control.throwIfCancelled();
        const CandidatePair& pair = crossing[p];
        const std::size_t i = pair.first, j = pair.second;
        if (pair.contact.kind == PairContact::cornerCuts &&
            cutsMeetOnlyAtCorner(triangles[i], triangles[j], pair.contact.i, pair.contact.j))
            continue;
        ++measured.constructedPairs;
        markIntersection(i, j, triangles, input, crossings, marks, groups);
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
    runInChunks(split.size(), control, [&](std::size_t k) {
        triangulateGroup(members[split[k]], triangles, marks, splitPieces[k]);
        inCanonicalOrder(splitPieces[k]);
    });
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
