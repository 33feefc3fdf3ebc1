#include "core/solid/triangle_arrangement.h"

#include "core/util/union_find.h"

#include <CGAL/Constrained_triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <optional>
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
CGAL::Orientation sideOf(const Corners& t, const ExactPoint& p)
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

// Most candidate pairs are neighbours in a mesh. Decides with predicates alone whether
// two triangles that share one or two corners meet nowhere else (then they leave nothing
// on each other); false when they share none or may meet elsewhere.
bool meetOnlyAtSharedCorners(const Corners& a, const Corners& b)
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
    const auto next = [](std::size_t k, std::size_t step) { return (k + step) % 3; };
    if (shared == 1) {
        const std::size_t i = std::size_t(
            std::find_if(matchInB.begin(), matchInB.end(), [](std::size_t m) { return m != none; }) - matchInB.begin());
        const std::size_t j = matchInB[i];
        const ExactPoint& v = a[i];
        const ExactPoint &a1 = a[next(i, 1)], &a2 = a[next(i, 2)], &b1 = b[next(j, 1)], &b2 = b[next(j, 2)];
        // Each corner's side of the other triangle's plane, decided once (most pairs).
        const CGAL::Orientation a1InB = sideOf(b, a1), a2InB = sideOf(b, a2);
        const CGAL::Orientation b1InA = sideOf(a, b1), b2InA = sideOf(a, b2);
        // a's other two corners strictly on one side of b's plane: a touches that plane
        // only at the shared corner (or the same the other way round).
        if (oneSide(a1InB, a2InB) || oneSide(b1InA, b2InA))
            return true;
        if (oppositeSides(a1InB, a2InB) && oppositeSides(b1InA, b2InA)) {
            // Each meets the other's plane in a segment from v along the planes' common
            // line: [v, p] and [v, q]. They share more than v only if p and q lie on the
            // same side of v (the angle p v q is 0, not 180 degrees). Deciding this here
            // keeps the exact intersection, which falls back to rationals at a shared
            // corner, for the few pairs that really cross.
            const ExactPoint p = segmentCrossing(a1, a2, b);
            const ExactPoint q = segmentCrossing(b1, b2, a);
            return CGAL::angle(p, v, q) == CGAL::OBTUSE;
        }
        if (b1InA != CGAL::COPLANAR || b2InA != CGAL::COPLANAR)
            return false;
        // In one plane (a fan in a flat region): the two corners at v are convex sectors,
        // which meet only at v iff a line along one of their four edges separates them.
        const auto beyond = [&](const ExactPoint& edge, const ExactPoint& own, const ExactPoint& p,
                                const ExactPoint& q) {
            return CGAL::coplanar_orientation(v, edge, own, p) == CGAL::NEGATIVE &&
                   CGAL::coplanar_orientation(v, edge, own, q) == CGAL::NEGATIVE;
        };
        return beyond(a1, a2, b1, b2) || beyond(a2, a1, b1, b2) || beyond(b1, b2, a1, a2) || beyond(b2, b1, a1, a2);
    }
    if (shared == 2) {
        // A shared edge: the planes meet in its line, which each triangle meets in the
        // edge alone; in one plane, the triangles meet only there when they lie on
        // opposite sides of it.
        const std::size_t i = std::size_t(std::find(matchInB.begin(), matchInB.end(), none) - matchInB.begin());
        std::size_t j = 0;
        while (j == matchInB[next(i, 1)] || j == matchInB[next(i, 2)])
            ++j;
        if (sideOf(a, b[j]) != CGAL::COPLANAR)
            return true;
        return CGAL::coplanar_orientation(a[next(i, 1)], a[next(i, 2)], a[i], b[j]) == CGAL::NEGATIVE;
    }
    return false;
}

// Records what triangles i and j leave on each other; those that overlap in their
// common plane become one group (triangulated together).
void markIntersection(std::size_t i, std::size_t j, const std::vector<Corners>& triangles, std::vector<Marks>& marks,
                      UnionFind& groups)
{
    if (meetOnlyAtSharedCorners(triangles[i], triangles[j]))
        return;
    const Triangle3 a(triangles[i][0], triangles[i][1], triangles[i][2]);
    const Triangle3 b(triangles[j][0], triangles[j][1], triangles[j][2]);
    if (!CGAL::do_intersect(a, b))
        return;
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

} // namespace

std::vector<ArrangedTriangle> arrangeTriangles(const std::vector<std::array<ExactPoint, 3>>& triangles,
                                               const TaskControl& control)
{
    const auto pairs = overlappingBoxes(triangles);
    std::vector<Marks> marks(triangles.size());
    UnionFind groups(triangles.size());
    constexpr std::size_t kCheckEvery = 4096;
    for (std::size_t p = 0; p < pairs.size(); ++p) {
        if (p % kCheckEvery == 0)
            control.throwIfCancelled();
        markIntersection(pairs[p].first, pairs[p].second, triangles, marks, groups);
    }

    std::vector<std::vector<std::size_t>> members(triangles.size());
    for (std::size_t i = 0; i < triangles.size(); ++i)
        members[groups.find(i)].push_back(i);
    std::vector<ArrangedTriangle> pieces;
    pieces.reserve(triangles.size());
    for (std::size_t root = 0; root < triangles.size(); ++root) {
        if (root % kCheckEvery == 0)
            control.throwIfCancelled();
        const std::vector<std::size_t>& group = members[root];
        if (group.empty())
            continue;
        const bool untouched = group.size() == 1 && marks[root].points.empty() && marks[root].segments.empty();
        if (untouched)
            pieces.push_back({triangles[root], root});
        else
            triangulateGroup(group, triangles, marks, pieces);
    }
    return pieces;
}

} // namespace trimlab::solid
