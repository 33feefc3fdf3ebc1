#include "core/skeleton/sparse_cholesky.h"

#include "core/util/memory_budget.h"

#include <iostream> // Eigen/MetisSupport reports METIS errors on std::cerr without including it

#include <Eigen/CholmodSupport>
#include <Eigen/MetisSupport>
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>

#include <dlfcn.h>

#include <cstdint>
#include <utility>
#include <vector>

namespace trimlab {

namespace {

// CHOLMOD's supernodal factorization opens OpenMP teams of a size compiled into the library
// (CHOLMOD_OMP_NUM_THREADS: 4 in Debian's build) whatever the machine has, and OpenBLAS's
// own threads run beside them. On 2 cores the 4 threads spin and yield against the BLAS
// threads, which costs about a third of the contraction's time
// (docs/measurements/2026-11-29-skeleton-stages.md). With dynamic teams the OpenMP runtime
// caps a team at the cores the load average leaves free, so a machine with idle cores still
// gets CHOLMOD's 4 threads. The dynamic setting belongs to the calling thread, so it is set
// before every call into CHOLMOD (a contraction may run on any worker thread). The runtime
// is whichever CHOLMOD brought (libgomp on Debian): looked up rather than linked, so a
// CHOLMOD without OpenMP needs nothing.
void useDynamicOpenMpTeams()
{
    using SetDynamic = void (*)(int);
    static const auto setDynamic = reinterpret_cast<SetDynamic>(dlsym(RTLD_DEFAULT, "omp_set_dynamic"));
    if (setDynamic)
        setDynamic(1);
}

// OpenBLAS runs on one thread. Its threads spin while they wait for work, and on a busy
// machine a descheduled one stalls the others, which makes a contraction ten to thirty
// times slower; on an idle machine one thread is no slower, as CHOLMOD's supernodes are
// small for threaded BLAS (docs/measurements/2026-11-29-skeleton-stages.md). Process-wide,
// and made before every call into CHOLMOD as the OpenMP setting above, so that nothing set
// in between lasts; looked up, so another BLAS needs nothing.
void useOneBlasThread()
{
    using SetNumThreads = void (*)(int);
    static const auto setNumThreads = reinterpret_cast<SetNumThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
    if (setNumThreads)
        setNumThreads(1);
}

// Both settings above, made before every call into CHOLMOD.
void setThreadsForCholmod()
{
    useDynamicOpenMpTeams();
    useOneBlasThread();
}

using Permutation = Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>;

const char* cholmodOrderingName(int ordering)
{
    switch (ordering) {
    case CHOLMOD_NATURAL:
        return "natural";
    case CHOLMOD_GIVEN:
        return "given";
    case CHOLMOD_AMD:
        return "AMD";
    case CHOLMOD_METIS:
        return "METIS";
    case CHOLMOD_NESDIS:
        return "NESDIS";
    case CHOLMOD_COLAMD:
        return "COLAMD";
    case CHOLMOD_POSTORDERED:
        return "natural (postordered)";
    default:
        return "unknown";
    }
}

std::string cholmodStatusText(int status)
{
    switch (status) {
    case CHOLMOD_NOT_INSTALLED:
        return "a CHOLMOD module it needs is not installed (e.g. METIS: no Partition module)";
    case CHOLMOD_OUT_OF_MEMORY:
        return "out of memory";
    case CHOLMOD_TOO_LARGE:
        return "the problem is too large for CHOLMOD's integer type";
    case CHOLMOD_INVALID:
        return "CHOLMOD rejected its input as invalid";
    case CHOLMOD_GPU_PROBLEM:
        return "CHOLMOD's GPU code failed";
    case CHOLMOD_NOT_POSDEF:
        return "the matrix is not positive definite";
    case CHOLMOD_DSMALL:
        return "the factor has a tiny diagonal entry";
    default:
        return "CHOLMOD status " + std::to_string(status);
    }
}

// OpenBLAS's work buffer (128 MiB on x86-64) with as much again for the factor's blocks.
constexpr std::uint64_t kBlasRoom = std::uint64_t(256) << 20;

// CHOLMOD through Eigen's wrapper. Eigen keeps the cholmod_factor protected and does not
// check cholmod_analyze's result (a failed analysis leaves a null factor that factorize
// would dereference), so this subclass exposes it for checking.
class CholmodFactor final : public SparseCholesky {
    struct Decomposition : Eigen::CholmodDecomposition<SkeletonSparseMatrix, Eigen::Lower> {
        [[nodiscard]] const cholmod_factor* factor() const { return this->m_cholmodFactor; }
    };

public:
    explicit CholmodFactor(int ordering) : m_requested(ordering)
    {
        cholmod_common& common = m_solver.cholmod();
        common.nmethods = 1; // exactly the requested ordering, no trial of alternatives
        common.method[0].ordering = ordering;
        common.postorder = 1;
        common.print = 0; // failures are reported through `error`, not printed
        // The supernodal factorization calls OpenBLAS, which takes a 128 MiB work buffer on
        // its first call and retries for ever when the system refuses it (under prlimit
        // --as). Where the memory budget leaves no room for that buffer, CHOLMOD's
        // simplicial factorization, which calls no BLAS, is used instead.
        if (memoryBudgetBytes() < kBlasRoom)
            common.supernodal = CHOLMOD_SIMPLICIAL;
    }

    bool analyze(const SkeletonSparseMatrix& lower, std::string& error) override
    {
        setThreadsForCholmod();
        m_solver.analyzePattern(lower);
        const cholmod_common& common = m_solver.cholmod();
        if (common.status < CHOLMOD_OK || m_solver.factor() == nullptr) {
            error = std::string("CHOLMOD's symbolic analysis with ") + cholmodOrderingName(m_requested) +
                    " ordering failed: " + cholmodStatusText(common.status) + ".";
            m_analyzed = false;
            return false;
        }
        m_analyzed = true;
        m_used = m_solver.factor()->ordering;
        m_supernodal = m_solver.factor()->is_super != 0;
        return true;
    }

    bool factorize(const SkeletonSparseMatrix& lower, std::string& error) override
    {
        if (!m_analyzed) {
            error = "CHOLMOD factorization requested before a successful analysis.";
            return false;
        }
        setThreadsForCholmod();
        m_solver.factorize(lower);
        const cholmod_common& common = m_solver.cholmod();
        if (m_solver.info() != Eigen::Success || common.status < CHOLMOD_OK || common.status == CHOLMOD_NOT_POSDEF) {
            error = "CHOLMOD's numeric factorization failed: " + cholmodStatusText(common.status) + " (column " +
                    std::to_string(m_solver.factor()->minor) + " of " + std::to_string(m_solver.factor()->n) + ").";
            return false;
        }
        return true;
    }

    bool solve(const Eigen::MatrixX3d& rhs, Eigen::MatrixX3d& x, std::string& error) override
    {
        setThreadsForCholmod();
        x = m_solver.solve(rhs);
        if (m_solver.info() != Eigen::Success) {
            error = "CHOLMOD's solve failed: " + cholmodStatusText(m_solver.cholmod().status) + ".";
            return false;
        }
        return true;
    }

    [[nodiscard]] std::string description() const override
    {
        std::string text = m_supernodal ? "CHOLMOD supernodal LLᵀ" : "CHOLMOD simplicial LDLᵀ";
        if (!m_analyzed)
            return text + ", " + cholmodOrderingName(m_requested) + " ordering requested";
        text += std::string(", ") + cholmodOrderingName(m_used) + " ordering";
        if (m_used != m_requested && !(m_requested == CHOLMOD_NATURAL && m_used == CHOLMOD_POSTORDERED))
            text += std::string(" (") + cholmodOrderingName(m_requested) + " requested)";
        return text;
    }

    [[nodiscard]] int usedOrdering() const { return m_used; }

private:
    Decomposition m_solver;
    int m_requested;
    int m_used = -1;
    bool m_supernodal = false;
    bool m_analyzed = false;
};

// Eigen's SimplicialLDLT with a compile-time ordering.
template <class Ordering>
class SimplicialFactor final : public SparseCholesky {
public:
    explicit SimplicialFactor(std::string ordering) : m_ordering(std::move(ordering)) {}

    bool analyze(const SkeletonSparseMatrix& lower, std::string& error) override
    {
        m_solver.analyzePattern(lower);
        if (m_solver.info() != Eigen::Success) {
            error = "Eigen SimplicialLDLT's symbolic analysis failed.";
            return false;
        }
        return true;
    }

    bool factorize(const SkeletonSparseMatrix& lower, std::string& error) override
    {
        m_solver.factorize(lower);
        if (m_solver.info() != Eigen::Success) {
            error = "Eigen SimplicialLDLT's numeric factorization failed (zero pivot).";
            return false;
        }
        return true;
    }

    bool solve(const Eigen::MatrixX3d& rhs, Eigen::MatrixX3d& x, std::string& error) override
    {
        x = m_solver.solve(rhs);
        if (m_solver.info() != Eigen::Success) {
            error = "Eigen SimplicialLDLT's solve failed.";
            return false;
        }
        return true;
    }

    [[nodiscard]] std::string description() const override
    {
        return "Eigen SimplicialLDLT, " + m_ordering + " ordering";
    }

private:
    Eigen::SimplicialLDLT<SkeletonSparseMatrix, Eigen::Lower, Ordering> m_solver;
    std::string m_ordering;
};

// A fixed symmetric permutation P applied before an inner factorization that keeps the
// given order: factorizes P·N·Pᵀ and solves N x = b as x = Pᵀ·solve(P·b).
class PermutedFactor final : public SparseCholesky {
public:
    PermutedFactor(std::unique_ptr<SparseCholesky> inner, Permutation permutation, std::string name)
        : m_inner(std::move(inner)), m_permutation(std::move(permutation)), m_name(std::move(name))
    {
    }

    bool analyze(const SkeletonSparseMatrix& lower, std::string& error) override
    {
        permute(lower);
        return m_inner->analyze(m_permuted, error);
    }

    bool factorize(const SkeletonSparseMatrix& lower, std::string& error) override
    {
        permute(lower);
        return m_inner->factorize(m_permuted, error);
    }

    bool solve(const Eigen::MatrixX3d& rhs, Eigen::MatrixX3d& x, std::string& error) override
    {
        const Eigen::MatrixX3d permutedRhs = m_permutation * rhs;
        Eigen::MatrixX3d y;
        if (!m_inner->solve(permutedRhs, y, error))
            return false;
        x = m_permutation.inverse() * y;
        return true;
    }

    [[nodiscard]] std::string description() const override
    {
        std::string inner = m_inner->description();
        if (const std::size_t comma = inner.find(','); comma != std::string::npos)
            inner.resize(comma);
        return inner + ", " + m_name;
    }

private:
    void permute(const SkeletonSparseMatrix& lower)
    {
        m_permuted.resize(lower.rows(), lower.cols());
        m_permuted.selfadjointView<Eigen::Lower>() = lower.selfadjointView<Eigen::Lower>().twistedBy(m_permutation);
    }

    std::unique_ptr<SparseCholesky> m_inner;
    Permutation m_permutation;
    std::string m_name;
    SkeletonSparseMatrix m_permuted;
};

// COLAMD's column ordering of A, as the old → new permutation P of AᵀA's rows and
// columns (Eigen's COLAMDOrdering already returns that direction).
Permutation colamdPermutation(const SkeletonSparseMatrix& a)
{
    SkeletonSparseMatrix compressed = a;
    compressed.makeCompressed();
    Permutation permutation;
    Eigen::COLAMDOrdering<int> ordering;
    ordering(compressed, permutation);
    return permutation;
}

int cholmodOrdering(SparseOrdering ordering)
{
    return ordering == SparseOrdering::Metis ? CHOLMOD_METIS : CHOLMOD_AMD;
}

} // namespace

const char* orderingName(SparseOrdering ordering)
{
    switch (ordering) {
    case SparseOrdering::Amd:
        return "AMD";
    case SparseOrdering::Colamd:
        return "COLAMD";
    case SparseOrdering::Metis:
        return "METIS";
    }
    return "unknown";
}

std::unique_ptr<SparseCholesky> makeSparseCholesky(SparseBackend backend, SparseOrdering ordering,
                                                   const SkeletonSparseMatrix* colamdSource)
{
    if (ordering == SparseOrdering::Colamd && colamdSource != nullptr) {
        std::unique_ptr<SparseCholesky> inner;
        if (backend == SparseBackend::Cholmod)
            inner = std::make_unique<CholmodFactor>(CHOLMOD_NATURAL);
        else
            inner = std::make_unique<SimplicialFactor<Eigen::NaturalOrdering<int>>>("natural");
        return std::make_unique<PermutedFactor>(std::move(inner), colamdPermutation(*colamdSource),
                                                "COLAMD ordering (of A, applied before factorizing)");
    }
    if (backend == SparseBackend::Cholmod)
        return std::make_unique<CholmodFactor>(cholmodOrdering(ordering));
    if (ordering == SparseOrdering::Metis)
        return std::make_unique<SimplicialFactor<Eigen::MetisOrdering<int>>>("METIS (Eigen MetisSupport)");
    return std::make_unique<SimplicialFactor<Eigen::AMDOrdering<int>>>("AMD");
}

bool cholmodHasMetis()
{
    // The 5-point Laplacian of a 24×24 grid plus the identity: SPD and large enough that
    // CHOLMOD really calls METIS_NodeND.
    const int side = 24, n = side * side;
    std::vector<Eigen::Triplet<double, int>> entries;
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            const int i = y * side + x;
            entries.emplace_back(i, i, 5.0);
            if (x + 1 < side)
                entries.emplace_back(i + 1, i, -1.0);
            if (y + 1 < side)
                entries.emplace_back(i + side, i, -1.0);
        }
    SkeletonSparseMatrix lower(n, n);
    lower.setFromTriplets(entries.begin(), entries.end());
    CholmodFactor factor(CHOLMOD_METIS);
    std::string error;
    return factor.analyze(lower, error) && factor.usedOrdering() == CHOLMOD_METIS;
}

} // namespace trimlab
