#include "core/solid/refined_soup.h"

#include "core/scene/scene.h"
#include "core/solid/triangle_arrangement.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <glm/vec4.hpp>

#include <algorithm>
#include <chrono>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace trimlab::solid {

namespace {

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
    const auto p = [&](int k) {
        return P(t.corners[std::size_t(k)].x, t.corners[std::size_t(k)].y, t.corners[std::size_t(k)].z);
    };
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
// per object, refined once; a stack whose deltas cancel bounds nothing and is dropped.
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
            corners[std::size_t(k)] = {t.corners[std::size_t(k)].x, t.corners[std::size_t(k)].y,
                                       t.corners[std::size_t(k)].z};
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

// The stacks that do not cancel, as exact triangles, with the index of their stack. Equal
// corners are one exact point (one handle), so that the merge and the arrangement's
// triangulations recognise them by identity.
std::vector<std::array<ExactPoint, 3>> exactTriangles(const std::vector<Stack>& stacks,
                                                      std::vector<std::size_t>& stackOf)
{
    std::map<std::array<double, 3>, ExactPoint> corners;
    const auto exactCorner = [&](const glm::dvec3& c) -> const ExactPoint& {
        const std::array<double, 3> key{c.x, c.y, c.z};
        const auto found = corners.find(key);
        if (found != corners.end())
            return found->second;
        return corners.emplace(key, ExactPoint(c.x, c.y, c.z)).first->second;
    };
    std::vector<std::array<ExactPoint, 3>> triangles;
    for (std::size_t s = 0; s < stacks.size(); ++s) {
        if (cancels(stacks[s].delta))
            continue;
        const auto& c = stacks[s].corners;
        triangles.push_back({exactCorner(c[0]), exactCorner(c[1]), exactCorner(c[2])});
        stackOf.push_back(s);
    }
    return triangles;
}

// Lexicographic order; one handle is equal to itself without evaluating it.
struct PointLess {
    bool operator()(const ExactPoint& a, const ExactPoint& b) const
    {
        return !CGAL::identical(a, b) && CGAL::compare_xyz(a, b) == CGAL::SMALLER;
    }
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
    std::vector<std::size_t> stackOf;
    const std::vector<ArrangedTriangle> pieces =
        arrangeTriangles(exactTriangles(stacks, stackOf), control, &soup.profile);
    control.throwIfCancelled();
    control.report("refine", 1, 2);
    const auto mergeStart = std::chrono::steady_clock::now();

    // Equal points become one vertex; faces over the same three vertices one face.
    std::map<ExactPoint, std::uint32_t, PointLess> pointIndex;
    std::unordered_map<CGAL::Handle::Id_type, std::uint32_t> indexOfHandle; ///< handles seen before
    std::map<std::array<std::uint32_t, 3>, std::size_t> faceIndex;
    std::vector<bool> firstReversed; ///< per face: the unorientedKey flag of its first face
    const std::size_t objectCount = scene.objects.size();
    for (const ArrangedTriangle& piece : pieces) {
        std::array<std::uint32_t, 3> v{};
        for (int k = 0; k < 3; ++k) {
            const ExactPoint& p = piece.corners[std::size_t(k)];
            const auto seen = indexOfHandle.find(p.id());
            if (seen != indexOfHandle.end()) {
                v[std::size_t(k)] = seen->second;
                continue;
            }
            const auto [it, inserted] = pointIndex.emplace(p, std::uint32_t(soup.points.size()));
            if (inserted)
                soup.points.push_back(p);
            v[std::size_t(k)] = it->second;
            indexOfHandle.emplace(p.id(), it->second);
        }
        if (CGAL::collinear(soup.points[v[0]], soup.points[v[1]], soup.points[v[2]]))
            continue; // bounds nothing
        // Faces over the same three vertices: the first one's orientation is the face's.
        bool reversed = false;
        const auto [it, inserted] = faceIndex.emplace(unorientedKey(v, reversed), soup.faces.size());
        if (inserted) {
            soup.faces.push_back({v, std::vector<int>(objectCount, 0), std::uint32_t(piece.source)});
            firstReversed.push_back(reversed);
        }
        RefinedFace& face = soup.faces[it->second];
        const bool sameAsFirst = reversed == firstReversed[it->second];
        const std::vector<int>& delta = stacks[stackOf[piece.source]].delta;
        for (std::size_t o = 0; o < delta.size(); ++o)
            face.delta[o] += sameAsFirst ? delta[o] : -delta[o];
    }
    const auto cancelled = std::remove_if(soup.faces.begin(), soup.faces.end(),
                                          [](const RefinedFace& face) { return cancels(face.delta); });
    soup.cancelledFaces = std::size_t(soup.faces.end() - cancelled) +
                          std::size_t(std::count_if(stacks.begin(), stacks.end(),
                                                    [](const Stack& stack) { return cancels(stack.delta); }));
    soup.faces.erase(cancelled, soup.faces.end());
    soup.profile.mergeMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - mergeStart).count();
    control.report("refine", 2, 2);
    return soup;
}

} // namespace trimlab::solid
