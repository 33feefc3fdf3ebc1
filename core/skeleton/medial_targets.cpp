#include "core/skeleton/medial_targets.h"

#include "core/skeleton/meyer_laplacian.h"

#include <glm/geometric.hpp>

#include <stdexcept>
#include <string>

namespace trimlab {

std::vector<std::optional<glm::dvec3>> medialTargets(const TriangleMesh& mesh,
                                                     const std::vector<std::optional<glm::dvec3>>& midpoints)
{
    if (midpoints.size() != mesh.vertexCount())
        throw std::invalid_argument("medialTargets: " + std::to_string(midpoints.size()) + " midpoints for " +
                                    std::to_string(mesh.vertexCount()) + " vertices");
    const std::vector<glm::dvec3> positions(mesh.positions.begin(), mesh.positions.end());
    const MeyerLaplacian laplacian = meyerLaplacian(positions, mesh.triangles);
    // (L·x)_i = Σ_j w_ij (x_i − x_j) = A_i · 2H_i · n_i.
    std::vector<glm::dvec3> curvatureNormal(positions.size(), glm::dvec3(0.0));
    for (const LaplacianEdge& e : laplacian.edges) {
        const glm::dvec3 d = e.weight * (positions[e.i] - positions[e.j]);
        curvatureNormal[e.i] += d;
        curvatureNormal[e.j] -= d;
    }
    std::vector<std::optional<glm::dvec3>> targets(positions.size());
    for (std::size_t v = 0; v < positions.size(); ++v) {
        if (!midpoints[v] || !(laplacian.area[v] > 0.0))
            continue;
        const double meanCurvature = glm::length(curvatureNormal[v]) / (2.0 * laplacian.area[v]);
        if (glm::length(*midpoints[v] - positions[v]) * meanCurvature <= kMaxHalfChordCurvature)
            targets[v] = midpoints[v];
    }
    return targets;
}

} // namespace trimlab
