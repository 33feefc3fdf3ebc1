#include "core/animation/hierarchical_partition.h"

#include <Eigen/Dense>

#include <algorithm>
#include <numeric>

namespace trimlab {

namespace {

// Members of every cluster and its spread; the state of the top-down loop.
struct ClusterSet {
    std::vector<std::uint32_t> labels;
    std::vector<std::vector<std::uint32_t>> members;
    std::vector<double> spread;   // Σ w·|f − mean|²
    std::vector<char> splittable; // cleared when a split failed
};

std::vector<double> weightedMean(const FeatureView& f, std::span<const double> w, const std::vector<std::uint32_t>& vs)
{
    std::vector<double> mean(f.dimension, 0.0);
    double mass = 0.0;
    for (const std::uint32_t v : vs) {
        mass += w[v];
        for (std::size_t c = 0; c < f.dimension; ++c)
            mean[c] += w[v] * f.values[v * f.dimension + c];
    }
    for (double& m : mean)
        m = mass > 0.0 ? m / mass : 0.0;
    return mean;
}

double spreadOf(const FeatureView& f, std::span<const double> w, const std::vector<std::uint32_t>& vs)
{
    const std::vector<double> mean = weightedMean(f, w, vs);
    double sum = 0.0;
    for (const std::uint32_t v : vs) {
        const double d = f.distance(v, mean);
        sum += w[v] * d * d;
    }
    return sum;
}

// Projection of each member's feature on the principal axis of the cluster's features.
std::vector<double> principalProjection(const FeatureView& f, std::span<const double> w,
                                        const std::vector<std::uint32_t>& vs)
{
    std::vector<double> projection;
    projection.reserve(vs.size());
    if (f.dimension == 1) {
        for (const std::uint32_t v : vs)
            projection.push_back(f.values[v]);
        return projection;
    }
    const std::vector<double> mean = weightedMean(f, w, vs);
    const auto d = Eigen::Index(f.dimension);
    Eigen::MatrixXd covariance = Eigen::MatrixXd::Zero(d, d);
    Eigen::VectorXd x(d);
    for (const std::uint32_t v : vs) {
        for (Eigen::Index c = 0; c < d; ++c)
            x(c) = f.values[v * f.dimension + std::size_t(c)] - mean[std::size_t(c)];
        covariance += w[v] * x * x.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(covariance);
    const Eigen::VectorXd axis = solver.eigenvectors().col(d - 1); // largest eigenvalue
    for (const std::uint32_t v : vs) {
        double p = 0.0;
        for (Eigen::Index c = 0; c < d; ++c)
            p += axis(c) * f.values[v * f.dimension + std::size_t(c)];
        projection.push_back(p);
    }
    return projection;
}

// The member nearest the weighted `fraction` percentile of the projection.
std::uint32_t percentileVertex(const std::vector<std::uint32_t>& vs, const std::vector<double>& projection,
                               std::span<const double> w, double fraction)
{
    std::vector<std::size_t> order(vs.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return projection[a] < projection[b]; });
    double total = 0.0;
    for (const std::uint32_t v : vs)
        total += w[v];
    double running = 0.0;
    for (const std::size_t i : order) {
        running += w[vs[i]];
        if (running >= fraction * total)
            return vs[i];
    }
    return vs[order.back()];
}

} // namespace

namespace {

// Splits cluster `c` in two connected halves; false when it cannot be split.
bool splitCluster(const VertexGraph& graph, const FeatureView& f, std::span<const double> w, int iterations,
                  std::uint32_t c, ClusterSet& set)
{
    const std::vector<std::uint32_t>& vs = set.members[c];
    if (vs.size() < 2 || !(set.spread[c] > 0.0))
        return false;
    const std::vector<double> projection = principalProjection(f, w, vs);
    std::vector<std::uint32_t> seeds{percentileVertex(vs, projection, w, 0.1),
                                     percentileVertex(vs, projection, w, 0.9)};
    if (seeds[0] == seeds[1] || f.distance(seeds[0], f.values.subspan(seeds[1] * f.dimension, f.dimension)) == 0.0) {
        const auto [low, high] = std::minmax_element(projection.begin(), projection.end());
        seeds = {vs[std::size_t(low - projection.begin())], vs[std::size_t(high - projection.begin())]};
        if (*low == *high)
            return false;
    }
    const std::vector<std::uint32_t> regions =
        refineRegions(graph, f, w, seeds, iterations, GrowthDomain{set.labels, c});
    std::vector<std::uint32_t> first;
    std::vector<std::uint32_t> second;
    for (const std::uint32_t v : vs)
        (regions[v] == 1 ? second : first).push_back(v);
    if (first.empty() || second.empty() || first.size() + second.size() != vs.size())
        return false;
    const auto added = std::uint32_t(set.members.size());
    for (const std::uint32_t v : second)
        set.labels[v] = added;
    set.spread[c] = spreadOf(f, w, first);
    set.spread.push_back(spreadOf(f, w, second));
    set.members[c] = std::move(first);
    set.members.push_back(std::move(second));
    set.splittable.push_back(1);
    return true;
}

} // namespace

VertexLabeling hierarchicalPartition(const VertexGraph& graph, const FeatureView& feature,
                                     std::span<const double> weights, std::size_t clusters, int iterations)
{
    ClusterSet set;
    const VertexLabeling components = connectedComponents(graph);
    set.labels = components.labels;
    set.members.resize(components.count);
    for (std::size_t v = 0; v < set.labels.size(); ++v)
        set.members[set.labels[v]].push_back(std::uint32_t(v));
    for (const std::vector<std::uint32_t>& vs : set.members)
        set.spread.push_back(spreadOf(feature, weights, vs));
    set.splittable.assign(set.members.size(), 1);
    while (set.members.size() < clusters) {
        std::size_t best = set.members.size();
        for (std::size_t c = 0; c < set.members.size(); ++c) {
            if (set.splittable[c] && set.spread[c] > 0.0 &&
                (best == set.members.size() || set.spread[c] > set.spread[best]))
                best = c;
        }
        if (best == set.members.size())
            break;
        if (!splitCluster(graph, feature, weights, iterations, std::uint32_t(best), set))
            set.splittable[best] = 0;
    }
    return canonicalLabeling(set.labels);
}

} // namespace trimlab
