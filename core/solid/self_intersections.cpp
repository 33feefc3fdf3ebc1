#include "core/solid/self_intersections.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <utility>
#include <vector>

namespace trimlab {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangle = Kernel::Triangle_3;
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;

Kernel::Point_3 point(const glm::vec3& p)
{
    return {double(p.x), double(p.y), double(p.z)};
}

bool shareVertex(const glm::uvec3& a, const glm::uvec3& b)
{
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (a[i] == b[j])
                return true;
    return false;
}

} // namespace

SelfIntersections selfIntersections(const TriangleMesh& mesh, const TaskControl& control)
{
    std::vector<Triangle> triangles;
    std::vector<std::size_t> source; // the mesh triangle of each kept triangle
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        const glm::uvec3& t = mesh.triangles[i];
        if (t.x >= mesh.positions.size() || t.y >= mesh.positions.size() || t.z >= mesh.positions.size())
            continue;
        const Triangle triangle(point(mesh.positions[t.x]), point(mesh.positions[t.y]), point(mesh.positions[t.z]));
        if (triangle.is_degenerate())
            continue;
        triangles.push_back(triangle);
        source.push_back(i);
    }
    std::vector<Box> boxes;
    boxes.reserve(triangles.size());
    for (std::size_t i = 0; i < triangles.size(); ++i)
        boxes.emplace_back(triangles[i].bbox(), i);
    std::vector<std::pair<std::size_t, std::size_t>> candidates;
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
        if (!shareVertex(mesh.triangles[source[a.info()]], mesh.triangles[source[b.info()]]))
            candidates.emplace_back(a.info(), b.info());
    });
    SelfIntersections found;
    std::vector<bool> involved(triangles.size(), false);
    for (std::size_t c = 0; c < candidates.size(); ++c) {
        if (c % 4096 == 0)
            control.throwIfCancelled();
        const auto [a, b] = candidates[c];
        if (!CGAL::do_intersect(triangles[a], triangles[b]))
            continue;
        ++found.pairs;
        for (const std::size_t t : {a, b}) {
            found.triangles += involved[t] ? 0 : 1;
            involved[t] = true;
        }
    }
    return found;
}

} // namespace trimlab
