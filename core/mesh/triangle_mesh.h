#pragma once
/// \file
/// The triangle mesh TrimLab renders: flat vertex and index buffers, nothing else.
/// Connectivity work (adjacency, smoothing, contraction) converts to OpenMesh on demand
/// (see openmesh_adapter.h); derived quantities are computed by free functions.

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace trimlab {

/// A triangle mesh as the GPU and the CPU reference consume it.
/// - `positions`: #V×3 floats, object-space coordinates.
/// - `triangles`: #F×3 vertex indices, counter-clockwise when seen from outside, so the
///   geometric normal (b−a)×(c−a) points out of the solid. A front-facing triangle
///   contributes +1 to the winding index of the points behind it (thesis 2.1).
/// Indices are always in range once a loader returned the mesh (loaders validate them).
struct TriangleMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::uvec3> triangles;

    [[nodiscard]] std::size_t vertexCount() const { return positions.size(); }
    [[nodiscard]] std::size_t triangleCount() const { return triangles.size(); }
    [[nodiscard]] bool empty() const { return triangles.empty(); }

    /// Element-wise equality (floats compare by value: -0.0f == 0.0f, NaN != NaN).
    friend bool operator==(const TriangleMesh&, const TriangleMesh&) = default;
};

/// Axis-aligned bounding box. `valid()` is false for an empty box.
struct Bounds {
    glm::dvec3 min{1.0e300};
    glm::dvec3 max{-1.0e300};

    [[nodiscard]] bool valid() const { return min.x <= max.x && min.y <= max.y && min.z <= max.z; }
    [[nodiscard]] glm::dvec3 center() const { return 0.5 * (min + max); }
    /// Radius of the bounding sphere centred at center(); 0 for an empty box.
    [[nodiscard]] double radius() const;
    void extend(const glm::dvec3& p);
    void extend(const Bounds& other);
};

/// Bounds of every vertex referenced or not; non-finite coordinates are skipped.
[[nodiscard]] Bounds computeBounds(const TriangleMesh& mesh);

/// Angle-weighted vertex normals (#V×3, unit length; zero for isolated vertices).
[[nodiscard]] std::vector<glm::vec3> vertexNormals(const TriangleMesh& mesh);

/// Appends `other` to `mesh`, offsetting its indices.
void appendMesh(TriangleMesh& mesh, const TriangleMesh& other);

} // namespace trimlab
