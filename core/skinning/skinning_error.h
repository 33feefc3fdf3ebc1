#pragma once
/// \file
/// How far a skinned approximation is from the original animation: E_RMS (thesis eq. 2.7,
/// after Kavan et al. 2010 [69]), per pose and per vertex.
///
/// Normalisation. Eq. 2.7 is printed as E_RMS = 1000·‖A − A′‖_F / (3nk) with A, A′ the
/// 3k×n coordinate matrices. Taken literally that is not a mean error: for a fixed
/// per-coordinate error ε it equals 1000·ε/√(3nk), shrinking as vertices or poses are
/// added, and the thesis's own Table 4.1 (E_RMS ≈ 2 for the 42321-vertex, 48-pose
/// elephant) would then mean errors of several model units. The text calls it the
/// "mean skinning approximation error" metric "proposed by [69]", whose definition is the
/// root mean square: 1000·‖A − A′‖_F / √(3nk). We follow that (the square root lost in
/// the printed equation restored); `eRms` is in thousandths of the animation's length
/// unit. Because that depends on the model's scale, `eRmsDiagonal` divides it by the
/// rest pose's bounding-box diagonal (scale-free, for comparing models), and `rmse` is
/// the plain per-vertex RMS distance ‖A − A′‖_F / √(nk) that Dem Bones prints ("RMSE"):
/// eRms = 1000·rmse / √3.

#include "core/animation/mesh_animation.h"
#include "core/skinning/skinning_reconstruction.h"

#include <cstddef>
#include <vector>

namespace trimlab {

struct SkinningError {
    double eRms = 0.0;             ///< 1000·‖A − A′‖_F / √(3nk), thousandths of a length unit
    double eRmsDiagonal = 0.0;     ///< eRms / (rest-pose bounding-box diagonal)
    double rmse = 0.0;             ///< ‖A − A′‖_F / √(nk), length units (Dem Bones' RMSE)
    double frobenius = 0.0;        ///< ‖A − A′‖_F, length units
    double maxDistance = 0.0;      ///< largest ‖v − v′‖ over all poses and vertices
    double diagonal = 0.0;         ///< the rest pose's bounding-box diagonal used above
    std::vector<double> perPose;   ///< #P values 1000·‖A_t − A′_t‖_F / √(3n)
    std::vector<double> perVertex; ///< #V values √(Σ_t ‖v_j^t − v′_j^t‖² / k): a heat map
};

/// Compares `approximation` with `original` (#P × #V each; throws std::invalid_argument
/// when the sizes differ or there are no poses). `restPose` picks the pose whose bounding
/// box gives `diagonal`. Sums run in a fixed order: the result is deterministic.
[[nodiscard]] SkinningError measureSkinningError(const std::vector<PosePositions>& original,
                                                 const std::vector<PosePositions>& approximation,
                                                 std::size_t restPose = 0);

/// ‖v_j − v′_j‖ for every vertex j of one pose (#V values; throws std::invalid_argument
/// when the sizes differ): the error heat map of the pose shown. perVertex above sums over
/// every pose, so an edit that moves one bone at a late pose barely changes it; this shows
/// the pose the user looks at.
[[nodiscard]] std::vector<double> poseVertexErrors(const PosePositions& original, const PosePositions& approximation);

/// The original poses of `animation` in double precision (#P × #V).
[[nodiscard]] std::vector<PosePositions> animationPositions(const MeshAnimation& animation);

} // namespace trimlab
