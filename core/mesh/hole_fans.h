#pragma once
/// \file
/// Closing a mesh's holes by fans: each boundary loop (boundary_loops.h) gets one new
/// vertex, the centroid of the loop's corners, and one triangle from each loop edge to
/// it. The new triangles depend on the connectivity alone, so the same fans close every
/// pose of an animation (poses share connectivity); each pose puts the new vertices at
/// the centroids of its own corners. Why: the winding index — and so every trim rule,
/// static or dynamic — is defined only for closed surfaces, and the animations
/// horse-gallop and horse-collapse have holes of 19–20 edges. A fan of a small, nearly
/// planar hole adds a cap of that size and nothing else; a long twisted loop would get a
/// cap that may cross the mesh (ear clipping on the rest pose is the alternative then).

#include "core/mesh/triangle_mesh.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace trimlab {

struct HoleFans {
    /// The corners of each loop, as boundaryLoops gives them.
    std::vector<std::vector<std::uint32_t>> loops;
    /// The centre of loop i is vertex firstCentre + i (firstCentre = #V of the open mesh).
    std::uint32_t firstCentre = 0;
    /// Σ loop sizes triangles (l[i], l[i + 1], centre), oriented like the mesh.
    std::vector<glm::uvec3> triangles;

    [[nodiscard]] bool empty() const { return loops.empty(); }
};

/// The fans that close the mesh of `triangles` over `vertexCount` vertices. Empty for a
/// closed mesh. Throws std::invalid_argument as boundaryLoops does.
[[nodiscard]] HoleFans holeFans(std::span<const glm::uvec3> triangles, std::size_t vertexCount);

/// `positions` (the open mesh's #V) followed by the centroid of each loop's corners in
/// these positions (#V + #loops). Requires positions.size() == fans.firstCentre.
[[nodiscard]] std::vector<glm::vec3> withHoleCentres(const HoleFans& fans, const std::vector<glm::vec3>& positions);

/// `mesh` closed by holeFans: its triangles followed by the fans, its positions followed
/// by the centres. A closed mesh comes back unchanged.
[[nodiscard]] TriangleMesh closeHoles(const TriangleMesh& mesh);

} // namespace trimlab
