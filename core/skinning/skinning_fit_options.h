#pragma once
/// \file
/// How one pose's bone transforms are fitted (thesis 4.1.1): which linear solver, how many
/// rigid (DQS) iterations, how many threads.

namespace trimlab {

/// The solver of the per-pose normal equations (4B×4B for LBS, 6B×6B per DQS iteration;
/// bone pairs that share no vertex give zero blocks).
enum class LinearSolverKind {
    Automatic, ///< Dense up to 600 unknowns (B ≤ 150 for LBS), Sparse above
    Dense,     ///< Eigen dense LDLᵀ: fastest for the usual tens of bones
    Sparse,    ///< Eigen SimplicialLDLT on the bone-pair block pattern: hundreds of bones
};

struct PoseFitOptions {
    LinearSolverKind solver = LinearSolverKind::Automatic;
    /// Levenberg–Marquardt iterations of the rigid (DQS) fit per pose; stops earlier when a
    /// step lowers the error by less than a relative 1e-6.
    unsigned rigidIterations = 20;
    /// Worker threads for the per-vertex work inside one pose (0 = hardware). Results do not
    /// depend on it: vertices are summed in fixed chunks, in chunk order.
    unsigned threads = 0;
};

} // namespace trimlab
