#include "core/solid/triangle_arrangement.h"

#include "core/util/union_find.h"

#include <CGAL/Constrained_triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

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

/// What other triangles leave on a triangle: points where they touch it, segments where
/// they cross it.
struct Marks {
    std::vector<ExactPoint> points;
    std::vector<std::array<ExactPoint, 2>> segments;
};

std::vector<std::pair<std::size_t, std::size_t>> overlappingBoxes(const std::vector<Triangle3>& triangles)
{
    std::vector<Box> boxes;
    boxes.reserve(triangles.size());
    for (std::size_t i = 0; i < triangles.size(); ++i)
        boxes.emplace_back(triangles[i].bbox(), i); // exact: the corners are doubles
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
        pairs.emplace_back(a.info(), b.info());
    });
    return pairs;
}

// Whether both corners q, r lie strictly on one side of the plane of `t`.
bool strictlyOnOneSide(const Triangle3& t, const ExactPoint& q, const ExactPoint& r)
{
    const CGAL::Orientation side = CGAL::orientation(t[0], t[1], t[2], q);
    return side != CGAL::COPLANAR && side == CGAL::orientation(t[0], t[1], t[2], r);
}

// Most candidate pairs are neighbours in a mesh. Decides with predicates alone whether
// two triangles that share one or two corners meet nowhere else (then they leave nothing
// on each other); false when they share none or may meet elsewhere.
bool meetOnlyAtSharedCorners(const Triangle3& a, const Triangle3& b)
{
    std::array<int, 3> matchInB{-1, -1, -1};
    int shared = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (a[i] == b[j]) {
                matchInB[std::size_t(i)] = j;
                ++shared;
            }
    if (shared == 1) {
        // a's other two corners strictly on one side of b's plane: a touches that plane
        // only at the shared corner (or the same the other way round).
        const int i = int(std::find_if(matchInB.begin(), matchInB.end(), [](int m) { return m >= 0; }) - matchInB.begin());
        const int j = matchInB[std::size_t(i)];
        return strictlyOnOneSide(b, a[(i + 1) % 3], a[(i + 2) % 3]) ||
               strictlyOnOneSide(a, b[(j + 1) % 3], b[(j + 2) % 3]);
    }
    if (shared == 2) {
        // A shared edge: the planes meet in its line, which each triangle meets in the
        // edge alone; in one plane, the triangles meet only there when they lie on
        // opposite sides of it.
        const int i = int(std::find(matchInB.begin(), matchInB.end(), -1) - matchInB.begin());
        int j = 0;
        while (j == matchInB[std::size_t((i + 1) % 3)] || j == matchInB[std::size_t((i + 2) % 3)])
            ++j;
        if (CGAL::orientation(a[0], a[1], a[2], b[j]) != CGAL::COPLANAR)
            return true;
        return CGAL::coplanar_orientation(a[(i + 1) % 3], a[(i + 2) % 3], a[i], b[j]) == CGAL::NEGATIVE;
    }
    return false;
}

// Records what triangles i and j leave on each other; those that overlap in their
// common plane become one group (triangulated together).
void markIntersection(std::size_t i, std::size_t j, const std::vector<Triangle3>& triangles, std::vector<Marks>& marks,
                      UnionFind& groups)
{
    const Triangle3& a = triangles[i];
    const Triangle3& b = triangles[j];
    if (meetOnlyAtSharedCorners(a, b) || !CGAL::do_intersect(a, b))
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
        xyz[std::size_t(axis)] = -(n[std::size_t(u)] * q.x() + n[std::size_t(v)] * q.y() + plane.d()) / n[std::size_t(axis)];
        return {xyz[0], xyz[1], xyz[2]};
    }
};

// Triangulates one group (coplanar triangles that overlap, or a lone triangle) with
// every member's edges and marks as constraints, and gives each piece to every member
// that covers it, in that member's orientation.
void triangulateGroup(const std::vector<std::size_t>& members, const std::vector<Triangle3>& triangles,
                      const std::vector<Marks>& marks, std::vector<ArrangedTriangle>& pieces)
{
    const Plane3 plane = triangles[members.front()].supporting_plane();
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
        const Triangle3& t = triangles[m];
        for (int k = 0; k < 3; ++k)
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
    for (std::size_t m : members)
        shadows.emplace_back(project(triangles[m][0]), project(triangles[m][1]), project(triangles[m][2]));
    for (auto f = triangulation.finite_faces_begin(); f != triangulation.finite_faces_end(); ++f) {
        const std::array<ExactPoint, 3> corners{*f->vertex(0)->info(), *f->vertex(1)->info(), *f->vertex(2)->info()};
        // Every member's edges are constraints, so a piece is inside a member or outside
        // it entirely; its centroid decides. A lone triangle is the hull of its points.
        const Point2 centre = CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
        for (std::size_t k = 0; k < members.size(); ++k) {
            if (members.size() > 1 && !shadows[k].has_on_bounded_side(centre))
                continue;
            ArrangedTriangle piece{corners, members[k]};
            if (shadows[k].orientation() == CGAL::CLOCKWISE) // the pieces run counter-clockwise
                std::swap(piece.corners[1], piece.corners[2]);
            pieces.push_back(std::move(piece));
        }
    }
}

} // namespace

std::vector<ArrangedTriangle> arrangeTriangles(const std::vector<std::array<ExactPoint, 3>>& input,
                                               const TaskControl& control)
{
    std::vector<Triangle3> triangles;
    triangles.reserve(input.size());
    for (const auto& t : input)
        triangles.emplace_back(t[0], t[1], t[2]);

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
            pieces.push_back({input[root], root});
        else
            triangulateGroup(group, triangles, marks, pieces);
    }
    return pieces;
}

} // namespace trimlab::solid
