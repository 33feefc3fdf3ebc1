#include "core/skinning/convex_vertex_weights.h"

#include "core/skinning/nnls.h"

#include <Eigen/Dense>

#include <algorithm>

namespace trimlab {

namespace {

// argmin x·G·x on the simplex: ‖R x‖² with R = Λ^½ Vᵀ from the eigen-decomposition G = V Λ Vᵀ.
Eigen::VectorXd simplexMinimiser(const Eigen::MatrixXd& gram)
{
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(gram);
    const Eigen::VectorXd root = eigen.eigenvalues().cwiseMax(0.0).cwiseSqrt();
    const Eigen::MatrixXd r = root.asDiagonal() * eigen.eigenvectors().transpose();
    const std::vector<double> zero(std::size_t(r.rows()), 0.0);
    const NnlsResult result =
        solveSimplexLeastSquares({r.data(), std::size_t(r.size())}, std::size_t(r.rows()), std::size_t(r.cols()), zero);
    return Eigen::Map<const Eigen::VectorXd>(result.x.data(), Eigen::Index(result.x.size()));
}

Eigen::MatrixXd subGram(const Eigen::MatrixXd& gram, const std::vector<Eigen::Index>& keep)
{
    Eigen::MatrixXd sub(Eigen::Index(keep.size()), Eigen::Index(keep.size()));
    for (std::size_t a = 0; a < keep.size(); ++a)
        for (std::size_t b = 0; b < keep.size(); ++b)
            sub(Eigen::Index(a), Eigen::Index(b)) = gram(keep[a], keep[b]);
    return sub;
}

} // namespace

VertexInfluences bestConvexInfluences(const Eigen::MatrixXd& gram, const std::vector<std::uint32_t>& bones,
                                      const VertexInfluences& old, std::size_t limit)
{
    limit = std::clamp<std::size_t>(limit, 1, kMaxInfluences);
    Eigen::VectorXd x = simplexMinimiser(gram);
    std::vector<Eigen::Index> order(bones.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = Eigen::Index(i);
    std::stable_sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) { return x(a) > x(b); });
    const auto positive = std::count_if(order.begin(), order.end(), [&](Eigen::Index i) { return x(i) > 0.0; });
    if (positive > Eigen::Index(limit)) {
        order.resize(limit);
        const Eigen::VectorXd y = simplexMinimiser(subGram(gram, order));
        x.setZero();
        for (std::size_t i = 0; i < order.size(); ++i)
            x(order[i]) = y(Eigen::Index(i));
    }
    Eigen::VectorXd current = Eigen::VectorXd::Zero(Eigen::Index(bones.size()));
    for (std::uint32_t i = 0; i < old.count; ++i)
        current(std::lower_bound(bones.begin(), bones.end(), old.bones[i]) - bones.begin()) = old.weights[i];
    if (old.count <= limit && !(x.dot(gram * x) < current.dot(gram * current)))
        return old;
    std::vector<std::pair<std::uint32_t, double>> influences;
    for (std::size_t i = 0; i < bones.size(); ++i)
        influences.emplace_back(bones[i], x(Eigen::Index(i)));
    return sparseInfluences(std::move(influences), old.bones[0], limit);
}

} // namespace trimlab
