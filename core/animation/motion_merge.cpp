#include "core/animation/motion_merge.h"

#include "core/animation/label_adjacency.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>
#include <set>
#include <vector>

namespace trimlab {

namespace {

// The sums of one segment at one pose that its rigid residual needs.
struct PoseSums {
    double n = 0.0;
    Eigen::Vector3d v = Eigen::Vector3d::Zero(), y = Eigen::Vector3d::Zero();
    Eigen::Matrix3d yv = Eigen::Matrix3d::Zero();
    double vv = 0.0, yy = 0.0;

    PoseSums& operator+=(const PoseSums& o)
    {
        n += o.n;
        v += o.v;
        y += o.y;
        yv += o.yv;
        vv += o.vv;
        yy += o.yy;
        return *this;
    }
};

using SegmentSums = std::vector<PoseSums>; // one per pose

// min_{R,c} Σ ‖R v + c − y‖² from the sums: centred spreads minus twice the trace of the
// best rotation against the cross-covariance (largest singular values, the last one
// negated when the best orthogonal map is a reflection).
double rigidResidual(const PoseSums& s)
{
    if (s.n <= 0.0)
        return 0.0;
    const Eigen::Vector3d vMean = s.v / s.n, yMean = s.y / s.n;
    const Eigen::Matrix3d cross = s.yv - s.n * yMean * vMean.transpose();
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(cross, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const double sign = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
    const Eigen::Vector3d sigma = svd.singularValues();
    const double spread = (s.vv - s.n * vMean.squaredNorm()) + (s.yy - s.n * yMean.squaredNorm());
    return std::max(0.0, spread - 2.0 * (sigma(0) + sigma(1) + sign * sigma(2)));
}

double residual(const SegmentSums& sums)
{
    double e = 0.0;
    for (const PoseSums& s : sums)
        e += rigidResidual(s);
    return e;
}

std::vector<SegmentSums> segmentSums(const MeshAnimation& animation, const VertexLabeling& labeling)
{
    std::vector<SegmentSums> sums(labeling.count, SegmentSums(animation.poseCount()));
    const std::vector<glm::vec3>& rest = animation.poses[animation.restPose];
    for (std::size_t t = 0; t < animation.poseCount(); ++t)
        for (std::size_t j = 0; j < labeling.labels.size(); ++j) {
            const Eigen::Vector3d v(rest[j].x, rest[j].y, rest[j].z);
            const glm::vec3& p = animation.poses[t][j];
            const Eigen::Vector3d y(p.x, p.y, p.z);
            PoseSums& s = sums[labeling.labels[j]][t];
            s.n += 1.0;
            s.v += v;
            s.y += y;
            s.yv += y * v.transpose();
            s.vv += v.squaredNorm();
            s.yy += y.squaredNorm();
        }
    return sums;
}

SegmentSums united(const SegmentSums& a, const SegmentSums& b)
{
    SegmentSums u = a;
    for (std::size_t t = 0; t < u.size(); ++t)
        u[t] += b[t];
    return u;
}

} // namespace

VertexLabeling mergeByMotion(const MeshAnimation& animation, const VertexGraph& graph, const VertexLabeling& labeling,
                             std::size_t count, std::size_t minVertices)
{
    if (labeling.count <= count)
        return labeling;
    std::vector<SegmentSums> sums = segmentSums(animation, labeling);
    std::vector<double> own(sums.size());
    for (std::size_t s = 0; s < sums.size(); ++s)
        own[s] = residual(sums[s]);
    std::vector<std::set<std::uint32_t>> neighbours;
    for (const auto& list : labelAdjacency(graph, labeling))
        neighbours.emplace_back(list.begin(), list.end());
    std::vector<std::uint32_t> into(labeling.count);
    for (std::uint32_t s = 0; s < into.size(); ++s)
        into[s] = s;
    std::vector<bool> alive(labeling.count, true);
    // Merge costs of adjacent pairs (a < b), recomputed only for pairs touching a merge.
    // An entry is stale once either segment has changed since it was pushed (versions).
    struct Entry {
        double cost;
        std::uint32_t a, b;
        unsigned versionA, versionB;
        bool operator<(const Entry& o) const
        {
            return cost != o.cost ? cost < o.cost : (a != o.a ? a < o.a : (b != o.b ? b < o.b : versionA < o.versionA));
        }
    };
    std::set<Entry> queue;
    std::vector<unsigned> version(labeling.count, 0);
    const auto pairCost = [&](std::uint32_t a, std::uint32_t b) {
        return residual(united(sums[a], sums[b])) - own[a] - own[b];
    };
    const auto push = [&](std::uint32_t a, std::uint32_t b) {
        if (a > b)
            std::swap(a, b);
        queue.insert({pairCost(a, b), a, b, version[a], version[b]});
    };
    for (std::uint32_t a = 0; a < labeling.count; ++a)
        for (std::uint32_t b : neighbours[a])
            if (a < b)
                push(a, b);
    for (std::uint32_t a = 0; a < labeling.count; ++a) // separate components: any partner
        if (neighbours[a].empty())
            for (std::uint32_t b = 0; b < labeling.count; ++b)
                if (b != a)
                    push(a, b);
    // The smallest segment under the minimum size and its cheapest partner, if any.
    const auto undersized = [&]() -> std::optional<std::pair<std::uint32_t, std::uint32_t>> {
        std::optional<std::uint32_t> small;
        for (std::uint32_t s = 0; s < alive.size(); ++s)
            if (alive[s] && sums[s][0].n < double(minVertices) && (!small || sums[s][0].n < sums[*small][0].n))
                small = s;
        if (!small)
            return std::nullopt;
        std::optional<std::uint32_t> partner;
        double best = std::numeric_limits<double>::infinity();
        const auto consider = [&](std::uint32_t n) {
            if (n == *small || !alive[n])
                return;
            const double cost = pairCost(std::min(*small, n), std::max(*small, n));
            if (!partner || cost < best) {
                best = cost;
                partner = n;
            }
        };
        for (std::uint32_t n : neighbours[*small])
            consider(n);
        if (!partner)
            for (std::uint32_t n = 0; n < alive.size(); ++n)
                consider(n);
        if (!partner)
            return std::nullopt;
        return std::pair{std::min(*small, *partner), std::max(*small, *partner)};
    };
    for (std::size_t remaining = labeling.count; remaining > count;) {
        std::uint32_t a = 0, b = 0;
        if (const auto forced = undersized()) {
            std::tie(a, b) = *forced;
        } else {
            if (queue.empty())
                break;
            const Entry top = *queue.begin();
            queue.erase(queue.begin());
            a = top.a;
            b = top.b;
            if (!alive[a] || !alive[b] || version[a] != top.versionA || version[b] != top.versionB)
                continue;
        }
        // b joins a.
        ++version[a];
        sums[a] = united(sums[a], sums[b]);
        own[a] = residual(sums[a]);
        alive[b] = false;
        into[b] = a;
        --remaining;
        for (std::uint32_t n : neighbours[b]) {
            neighbours[n].erase(b);
            if (n != a) {
                neighbours[n].insert(a);
                neighbours[a].insert(n);
            }
        }
        neighbours[b].clear();
        neighbours[a].erase(b);
        for (std::uint32_t n : neighbours[a])
            if (alive[n])
                push(a, n);
        if (neighbours[a].empty()) // a whole component now: may join any segment
            for (std::uint32_t n = 0; n < labeling.count; ++n)
                if (alive[n] && n != a)
                    push(a, n);
    }
    std::vector<std::uint32_t> labels(labeling.labels.size());
    for (std::size_t v = 0; v < labels.size(); ++v) {
        std::uint32_t s = labeling.labels[v];
        while (into[s] != s)
            s = into[s];
        labels[v] = s;
    }
    return canonicalLabeling(labels);
}

} // namespace trimlab
