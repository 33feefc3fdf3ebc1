// CGAL's experimental autorefinement checks the configurations it does not handle with
// CGAL_assertion only; without the check it runs into undefined behaviour on them (on the
// shared cow mesh: a missing intersection node, then front() of an empty list). The assertions stay on in this file
// so that such input throws, and the user gets a message instead of a crash.
#ifdef NDEBUG
#undef NDEBUG
#endif
#include "core/solid/refined_soup.h"

#include "core/scene/scene.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Surface_mesh.h>

#include <glm/vec4.hpp>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>

namespace trimlab::solid {

namespace {

// The refinement runs in the exact kernel: CGAL's autorefinement would round the
// intersection points of a double-precision mesh to doubles, and then faces meeting along
// an intersection curve no longer meet exactly there (their order around the curve's
// edges, which the windings rest on, would be wrong).
using Mesh = CGAL::Surface_mesh<ExactPoint>;
using FaceIndex = Mesh::Face_index;
using StackMap = Mesh::Property_map<FaceIndex, int>;

// Keeps each face's stack through the refinement: a face split by an intersection hands
// its stack to every sub-face (the corefinement visitor protocol: one
// before_subface_creations, then after_subface_created per new face).
struct StackKeeper : CGAL::Polygon_mesh_processing::Corefinement::Default_visitor<Mesh> {
    StackMap objects;
    std::shared_ptr<int> current = std::make_shared<int>(0);
    const TaskControl* control = nullptr;

    void before_subface_creations(FaceIndex split, const Mesh&) { *current = objects[split]; }
    void after_subface_created(FaceIndex created, const Mesh&) { objects[created] = *current; }
    void after_subface_creations(const Mesh&)
    {
        if (control)
            control->throwIfCancelled();
    }
};

struct InputTriangle {
    std::array<glm::dvec3, 3> corners;
    int object = 0;
};

std::vector<InputTriangle> worldTriangles(const Scene& scene)
{
    std::vector<InputTriangle> triangles;
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        const SceneObject& object = scene.objects[o];
        for (const glm::uvec3& t : object.mesh.triangles) {
            InputTriangle triangle;
            triangle.object = int(o);
            for (int k = 0; k < 3; ++k)
                triangle.corners[std::size_t(k)] =
                    glm::dvec3(object.modelMatrix * glm::dvec4(glm::dvec3(object.mesh.positions[t[k]]), 1.0));
            triangles.push_back(triangle);
        }
    }
    return triangles;
}

bool isDegenerate(const InputTriangle& t)
{
    using P = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
    const auto p = [&](int k) { return P(t.corners[std::size_t(k)].x, t.corners[std::size_t(k)].y, t.corners[std::size_t(k)].z); };
    return CGAL::collinear(p(0), p(1), p(2));
}

// A key for a triangle whatever its orientation: its corners in cyclic order from the
// smallest, the other two ascending. `reversed` tells whether that ascending order runs
// against the triangle's own cyclic order; two triangles with one key run the same way
// round iff their `reversed` agree.
template <class T>
std::array<T, 3> unorientedKey(std::array<T, 3> corners, bool& reversed)
{
    std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
    reversed = corners[1] > corners[2];
    if (reversed)
        std::swap(corners[1], corners[2]);
    return corners;
}

// Identical input triangles (the same three corners, either orientation: a doubly
// covered surface, an object and its inside-out copy) are one stack with a winding delta
// per object: the refinement cannot take coplanar overlaps three at a time, and needs
// only one of them.
struct Stack {
    std::array<glm::dvec3, 3> corners; ///< the first triangle's, in its orientation
    bool reversed = false;             ///< the first triangle's unorientedKey flag
    std::vector<int> delta;
};

std::vector<Stack> stackTriangles(const std::vector<InputTriangle>& triangles, std::size_t objects)
{
    std::vector<Stack> stacks;
    std::map<std::array<std::array<double, 3>, 3>, std::size_t> index;
    for (const InputTriangle& t : triangles) {
        std::array<std::array<double, 3>, 3> corners;
        for (int k = 0; k < 3; ++k)
            corners[std::size_t(k)] = {t.corners[std::size_t(k)].x, t.corners[std::size_t(k)].y, t.corners[std::size_t(k)].z};
        bool reversed = false;
        const auto [it, inserted] = index.emplace(unorientedKey(corners, reversed), stacks.size());
        if (inserted)
            stacks.push_back({t.corners, reversed, std::vector<int>(objects, 0)});
        Stack& stack = stacks[it->second];
        stack.delta[std::size_t(t.object)] += reversed == stack.reversed ? 1 : -1;
    }
    return stacks;
}

bool cancels(const std::vector<int>& delta)
{
    return std::all_of(delta.begin(), delta.end(), [](int d) { return d == 0; });
}

// The stacks as one halfedge mesh: vertices shared where the position is the same; a
// face the mesh cannot take there (a non-manifold edge or vertex) gets its own copies of
// its corners, so every stack is in. Sets each face's stack.
Mesh buildMesh(const std::vector<Stack>& stacks, StackMap& stackOf)
{
    Mesh mesh;
    stackOf = mesh.add_property_map<FaceIndex, int>("f:stack", 0).first;
    std::map<std::array<double, 3>, Mesh::Vertex_index> shared;
    const auto vertexAt = [&](const glm::dvec3& p) {
        const std::array<double, 3> key{p.x, p.y, p.z};
        auto it = shared.find(key);
        if (it == shared.end())
            it = shared.emplace(key, mesh.add_vertex(ExactPoint(p.x, p.y, p.z))).first;
        return it->second;
    };
    for (std::size_t s = 0; s < stacks.size(); ++s) {
        if (cancels(stacks[s].delta))
            continue;
        const auto& c = stacks[s].corners;
        FaceIndex face = mesh.add_face(vertexAt(c[0]), vertexAt(c[1]), vertexAt(c[2]));
        if (face == Mesh::null_face()) {
            std::array<Mesh::Vertex_index, 3> own;
            for (int k = 0; k < 3; ++k)
                own[std::size_t(k)] =
                    mesh.add_vertex(ExactPoint(c[std::size_t(k)].x, c[std::size_t(k)].y, c[std::size_t(k)].z));
            face = mesh.add_face(own[0], own[1], own[2]);
        }
        stackOf[face] = int(s);
    }
    return mesh;
}

struct PointLess {
    bool operator()(const ExactPoint& a, const ExactPoint& b) const { return CGAL::compare_xyz(a, b) == CGAL::SMALLER; }
};

} // namespace

RefinedSoup refineScene(const Scene& scene, const TaskControl& control)
{
    RefinedSoup soup;
    std::vector<InputTriangle> triangles = worldTriangles(scene);
    soup.inputTriangles = triangles.size();
    const auto degenerate = std::remove_if(triangles.begin(), triangles.end(), isDegenerate);
    soup.degenerateTriangles = std::size_t(triangles.end() - degenerate);
    triangles.erase(degenerate, triangles.end());
    control.report("refine", 0, 2);

    const std::vector<Stack> stacks = stackTriangles(triangles, scene.objects.size());
    StackMap stackOf;
    Mesh mesh = buildMesh(stacks, stackOf);
    StackKeeper keeper;
    keeper.objects = stackOf;
    keeper.control = &control;
    try {
        CGAL::Polygon_mesh_processing::experimental::autorefine(mesh, CGAL::parameters::visitor(keeper));
    } catch (const CGAL::Polygon_mesh_processing::Corefinement::Triple_intersection_exception&) {
        throw std::runtime_error("three faces overlap in one plane (coplanar faces that are not identical "
                                 "copies): the exact refinement cannot split them; move one of the objects a "
                                 "little, or remove the duplicated part of the surface");
    } catch (const CGAL::Failure_exception& failure) {
        throw std::runtime_error("the exact refinement (CGAL's autorefinement) met an intersection pattern it does "
                                 "not handle (its check '" + failure.expression() + "' failed); no solid was "
                                 "exported");
    }
    control.throwIfCancelled();
    control.report("refine", 1, 2);

    // Equal points become one vertex; faces over the same three vertices one face.
    std::map<ExactPoint, std::uint32_t, PointLess> pointIndex;
    std::map<std::array<std::uint32_t, 3>, std::size_t> faceIndex;
    std::vector<bool> firstReversed; ///< per face: the unorientedKey flag of its first face
    const std::size_t objectCount = scene.objects.size();
    for (FaceIndex f : mesh.faces()) {
        std::array<std::uint32_t, 3> v{};
        int k = 0;
        for (Mesh::Vertex_index vertex : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
            const ExactPoint& p = mesh.point(vertex);
            const auto [it, inserted] = pointIndex.emplace(p, std::uint32_t(soup.points.size()));
            if (inserted)
                soup.points.push_back(p);
            v[std::size_t(k++)] = it->second;
        }
        if (CGAL::collinear(soup.points[v[0]], soup.points[v[1]], soup.points[v[2]]))
            continue; // bounds nothing
        // Faces over the same three vertices: the first one's orientation is the face's.
        bool reversed = false;
        const auto [it, inserted] = faceIndex.emplace(unorientedKey(v, reversed), soup.faces.size());
        if (inserted) {
            soup.faces.push_back({v, std::vector<int>(objectCount, 0)});
            firstReversed.push_back(reversed);
        }
        RefinedFace& face = soup.faces[it->second];
        const bool sameAsFirst = reversed == firstReversed[it->second];
        const std::vector<int>& delta = stacks[std::size_t(stackOf[f])].delta;
        for (std::size_t o = 0; o < delta.size(); ++o)
            face.delta[o] += sameAsFirst ? delta[o] : -delta[o];
    }
    const auto cancelled = std::remove_if(soup.faces.begin(), soup.faces.end(),
                                          [](const RefinedFace& face) { return cancels(face.delta); });
    soup.cancelledFaces = std::size_t(soup.faces.end() - cancelled) +
                          std::size_t(std::count_if(stacks.begin(), stacks.end(),
                                                    [](const Stack& stack) { return cancels(stack.delta); }));
    soup.faces.erase(cancelled, soup.faces.end());
    control.report("refine", 2, 2);
    return soup;
}

} // namespace trimlab::solid
