#include "core/skinning/skinning_weights.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace trimlab {

namespace {

void requireLabels(const VertexGraph& graph, std::size_t positions, const VertexLabeling& segmentation)
{
    if (graph.vertexCount() != positions || segmentation.labels.size() != positions)
        throw std::invalid_argument("skinning weights: " + std::to_string(positions) + " rest positions, " +
                                    std::to_string(graph.vertexCount()) + " graph vertices and " +
                                    std::to_string(segmentation.labels.size()) + " labels");
    for (std::size_t v = 0; v < positions; ++v)
        if (segmentation.labels[v] >= segmentation.count)
            throw std::invalid_argument("skinning weights: vertex " + std::to_string(v) + " has the label " +
                                        std::to_string(segmentation.labels[v]) + " of " +
                                        std::to_string(segmentation.count));
}

double meanEdgeLength(const VertexGraph& graph, std::span<const glm::dvec3> p)
{
    double sum = 0.0;
    for (std::size_t u = 0; u < graph.vertexCount(); ++u)
        for (std::uint32_t v : graph.neighborsOf(u))
            sum += glm::length(p[u] - p[v]);
    return graph.neighbors.empty() ? 1.0 : sum / double(graph.neighbors.size());
}

// I + t·L with L the inverse-edge-length graph Laplacian.
Eigen::SparseMatrix<double> heatMatrix(const VertexGraph& graph, std::span<const glm::dvec3> p, double t)
{
    const double mean = meanEdgeLength(graph, p);
    const double floor = 1e-12 * (mean > 0.0 ? mean : 1.0);
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(graph.neighbors.size() + graph.vertexCount());
    for (std::size_t u = 0; u < graph.vertexCount(); ++u) {
        double diagonal = 1.0;
        for (std::uint32_t v : graph.neighborsOf(u)) {
            const double w = t * (mean > 0.0 ? mean : 1.0) / std::max(glm::length(p[u] - p[v]), floor);
            triplets.emplace_back(Eigen::Index(u), Eigen::Index(v), -w);
            diagonal += w;
        }
        triplets.emplace_back(Eigen::Index(u), Eigen::Index(u), diagonal);
    }
    const Eigen::Index n = Eigen::Index(graph.vertexCount());
    Eigen::SparseMatrix<double> matrix(n, n);
    matrix.setFromTriplets(triplets.begin(), triplets.end());
    return matrix;
}

} // namespace

SkinningWeights rigidWeights(const VertexLabeling& segmentation)
{
    SkinningWeights weights;
    weights.boneCount = segmentation.count;
    weights.vertices.resize(segmentation.labels.size());
    for (std::size_t v = 0; v < segmentation.labels.size(); ++v) {
        weights.vertices[v].bones[0] = segmentation.labels[v];
        weights.vertices[v].weights[0] = 1.0;
        weights.vertices[v].count = 1;
    }
    return weights;
}

SkinningWeights segmentationWeights(const VertexGraph& graph, std::span<const glm::dvec3> restPositions,
                                    const VertexLabeling& segmentation, const SkinningWeightOptions& options,
                                    const TaskControl& control)
{
    requireLabels(graph, restPositions.size(), segmentation);
    if (!(options.borderWidth > 0.0))
        return rigidWeights(segmentation);
    const double t = 0.5 * options.borderWidth * options.borderWidth;
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(heatMatrix(graph, restPositions, t));
    if (solver.info() != Eigen::Success)
        throw std::runtime_error("skinning weights: the heat system could not be factored");
    const std::size_t n = restPositions.size();
    std::vector<std::vector<std::pair<std::uint32_t, double>>> candidates(n);
    Eigen::VectorXd indicator(static_cast<Eigen::Index>(n));
    control.report("weights", 0, segmentation.count);
    for (std::uint32_t b = 0; b < segmentation.count; ++b) {
        control.throwIfCancelled();
        for (std::size_t v = 0; v < n; ++v)
            indicator(Eigen::Index(v)) = segmentation.labels[v] == b ? 1.0 : 0.0;
        const Eigen::VectorXd w = solver.solve(indicator);
        for (std::size_t v = 0; v < n; ++v)
            if (w(Eigen::Index(v)) > 1e-6) // far tails of the heat kernel carry nothing useful
                candidates[v].emplace_back(b, w(Eigen::Index(v)));
        control.report("weights", b + 1, segmentation.count);
    }
    SkinningWeights weights;
    weights.boneCount = segmentation.count;
    weights.vertices.resize(n);
    for (std::size_t v = 0; v < n; ++v)
        weights.vertices[v] = sparseInfluences(std::move(candidates[v]), segmentation.labels[v]);
    return weights;
}

SkinningWeights sparseWeightsFromDense(std::span<const double> dense, std::size_t vertexCount, std::size_t boneCount)
{
    if (dense.size() != vertexCount * boneCount)
        throw std::invalid_argument("skinning weights: " + std::to_string(dense.size()) + " values for " +
                                    std::to_string(vertexCount) + "×" + std::to_string(boneCount));
    SkinningWeights weights;
    weights.boneCount = boneCount;
    weights.vertices.resize(vertexCount);
    for (std::size_t v = 0; v < vertexCount; ++v) {
        std::vector<std::pair<std::uint32_t, double>> row;
        for (std::size_t b = 0; b < boneCount; ++b) {
            const double w = dense[v * boneCount + b];
            if (!std::isfinite(w))
                throw std::invalid_argument("skinning weights: vertex " + std::to_string(v) +
                                            " has a weight that is not finite");
            row.emplace_back(std::uint32_t(b), w);
        }
        weights.vertices[v] = sparseInfluences(std::move(row), 0);
    }
    return weights;
}

} // namespace trimlab
