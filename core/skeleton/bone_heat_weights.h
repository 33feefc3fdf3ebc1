#pragma once
/// \file
/// Skinning weights by heat diffusion from the bones (Berenguer & Moreno III.E, after
/// Baran & Popović 2007, "Automatic Rigging and Animation of 3D Characters"): for every
/// bone i the weights wⁱ solve
///
///     −Δwⁱ + H wⁱ = H pⁱ                                              (eq. 14)
///
/// with Δ the Meyer cotangent Laplacian (meyer_laplacian.h) and H, pⁱ the heat terms of
/// bone_heat_terms.h. Multiplied by the diagonal of mixed areas A the system becomes the
/// symmetric positive definite (L + A·H) wⁱ = A·H·pⁱ: one matrix for every bone, so it is
/// factorized once (sparse Cholesky: CHOLMOD, or Eigen's SimplicialLDLT) and solved for
/// all bones (right-hand sides in batches). Summing over i gives (L + AH)·Σwⁱ = AH·1,
/// whose solution is Σwⁱ = 1: the raw weights already form a partition of unity.
///
/// Sparse weights for skinning: per vertex the 4 largest raw weights are kept, negative
/// ones (the discrete Laplacian is not monotone next to obtuse angles) become 0, and the
/// rest is renormalised to sum 1.
///
/// Vertices without a visible bone (H_jj = 0) get their weights from diffusion alone.
/// A connected component of the mesh in which no vertex has a visible bone has no heat
/// source at all, and its equations would be singular (the Laplacian only fixes the
/// weights up to a constant there): such a component's vertices are pinned to their
/// nearest bone(s) — the equation becomes w_j = p̃_j, with p̃ splitting 1 equally over the
/// equidistant nearest bones whether visible or not. The same fallback applies to a
/// vertex whose four largest weights are all ≤ 0 (in practice never: they sum to 1).

#include "core/mesh/triangle_mesh.h"
#include "core/skeleton/bone_heat_terms.h"
#include "core/skeleton/contraction_options.h"
#include "core/skeleton/skeleton.h"

#include "core/util/task_control.h"

#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace trimlab {

/// Influences per vertex (glTF's JOINTS_0/WEIGHTS_0 hold four).
inline constexpr std::size_t kBoneInfluences = 4;

/// Sparse per-vertex skinning weights over the bones of a SkeletonRig (bone indices into
/// rig.bones). #V entries each. Per vertex the used slots come first, sorted by
/// decreasing weight (ties: smaller bone first); weights are in (0, 1] and sum to 1 up to
/// float rounding; unused slots hold bone −1 and weight 0.
struct BoneWeights {
    std::vector<std::array<int, kBoneInfluences>> bones;
    std::vector<std::array<float, kBoneInfluences>> weights;

    [[nodiscard]] std::size_t vertexCount() const { return bones.size(); }
};

/// One vertex's BoneWeights entry from its weight per bone: `candidates` holds (weight,
/// bone) pairs, a negative or non-finite weight counting as 0. The kBoneInfluences
/// largest (ties to the lower bone) are renormalised to sum 1 into `bones` / `weights`,
/// unused slots −1 and 0. Returns false, every slot unused, when nothing positive is left.
/// Reorders `candidates`.
bool strongestInfluences(std::vector<std::pair<double, int>>& candidates, std::array<int, kBoneInfluences>& bones,
                         std::array<float, kBoneInfluences>& weights);

struct BoneHeatOptions {
    BoneHeatTermOptions terms;
    /// The factorization (contraction_options.h). SparseOrdering::Colamd orders the
    /// columns of the symmetric system matrix itself (COLAMD is meant for the AᵀA of a
    /// rectangular A; here the system is already square, so AMD or METIS is the natural
    /// choice and COLAMD is offered only so that one --ordering flag can drive both).
    SparseBackend backend = SparseBackend::Cholmod;
    SparseOrdering ordering = SparseOrdering::Metis;
};

/// What the solver did, for reports and Table III's "weights" column.
struct BoneHeatReport {
    double laplacianMs = 0.0;         ///< Meyer Laplacian
    double heatTermsMs = 0.0;         ///< nearest bones and visibility rays
    double factorizationMs = 0.0;     ///< symbolic analysis + numeric factorization
    double solveMs = 0.0;             ///< all right-hand sides
    double sparsifyMs = 0.0;          ///< top-4 selection and normalisation
    std::size_t hiddenVertices = 0;   ///< vertices without a visible nearest bone (H_jj = 0)
    std::size_t pinnedVertices = 0;   ///< in components without any heat source (see file comment)
    std::size_t fallbackVertices = 0; ///< whose kept weights were all ≤ 0
    std::size_t skippedTriangles = 0; ///< degenerate triangles left out of the Laplacian
    std::string factorization;        ///< e.g. "CHOLMOD supernodal LLᵀ, METIS ordering"
    std::string note;                 ///< non-empty when the requested backend failed and the fallback ran

    [[nodiscard]] double totalMs() const { return laplacianMs + heatTermsMs + factorizationMs + solveMs + sparsifyMs; }
};

/// Computes the weights of every bone of `rig` over `mesh` in the constructor; the
/// results stay available for display (the dense column of one bone is the heat map of
/// the paper's Fig. 12). Degenerate triangles, obtuse angles and isolated vertices never
/// produce NaN weights.
class BoneHeatSolver {
public:
    /// Throws std::invalid_argument for a rig without bones or with joint indices out of
    /// range or non-finite joints (boneHeatTerms), or a mesh without vertices; std::out_of_range
    /// for a triangle index ≥ #V; std::runtime_error when both the requested factorization
    /// and the SimplicialLDLT fallback fail; OperationCancelled when `control` asks to stop
    /// (stages "visibility", "weights").
    BoneHeatSolver(const TriangleMesh& mesh, const SkeletonRig& rig, const BoneHeatOptions& options = {},
                   const TaskControl& control = {});

    [[nodiscard]] const BoneWeights& weights() const { return m_weights; }
    [[nodiscard]] std::size_t boneCount() const { return m_boneCount; }
    [[nodiscard]] std::size_t vertexCount() const { return m_weights.vertexCount(); }
    /// The raw solution wⁱ of eq. 14 for bone `bone` at every vertex (#V values, before the
    /// top-4 selection; may be slightly negative or above 1). Throws std::out_of_range for
    /// a bone outside [0, boneCount()).
    [[nodiscard]] std::vector<double> boneWeightColumn(int bone) const;
    [[nodiscard]] const BoneHeatTerms& heatTerms() const { return m_terms; }
    [[nodiscard]] const BoneHeatReport& report() const { return m_report; }

private:
    std::size_t m_boneCount = 0;
    std::vector<double> m_columns; // bone-major: m_columns[bone·#V + vertex]
    BoneHeatTerms m_terms;
    BoneWeights m_weights;
    BoneHeatReport m_report;
};

/// The sparse weights alone: BoneHeatSolver(mesh, rig, options, control).weights().
[[nodiscard]] BoneWeights boneHeatWeights(const TriangleMesh& mesh, const SkeletonRig& rig,
                                          const BoneHeatOptions& options = {}, const TaskControl& control = {});

} // namespace trimlab
