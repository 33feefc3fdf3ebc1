#pragma once
/// \file
/// Skinning decomposition: fitting bone transforms, weights and rest positions together by
/// alternating exact block updates, so that the exported skin plays what was fitted, in
/// the manner of Le & Deng's SSDR (2012, the method behind Electronic Arts' Dem Bones).
/// It minimises
///     E = Σ_t Σ_j ‖Σ_b w_bj M_b^t v_j − y_j^t‖²
/// (rest positions v_j, convex weights w_bj — 4 per vertex unless asked for up to 8 —,
/// target poses y^t) where M_b^t maps the rest pose to pose t and is either
/// - rigid (`rigidJoints`): x ↦ R x + t, blended linearly — exactly what a glTF skin
///   plays, so the exported file reproduces the fit (skinning_gltf.h); or
/// - affine: the classical rest-to-pose LBS of thesis 2.3.2, whose export must drop the
///   shear and scale (a rigid approximation).
/// The blocks, each minimised exactly in its variables (or left unchanged), so E never
/// rises between re-seedings:
/// 1. transforms: per pose — rigid: RigidJointSolver (weighted Procrustes bone by bone,
///    then all translations by least squares), warm-started; affine: the rest-to-pose
///    least-squares fit (skinning_pose_fit.h);
/// 2. weights: per vertex, the best convex weights (≤ maxInfluences) over its own bones
///    and those of its mesh neighbours (convex_vertex_weights.h), kept only when strictly
///    better — the
///    thesis's weight corrections (eq. 4.13–4.15) computed against this model;
/// 3. rest positions: per vertex, the 3×3 least-squares solve of the thesis's vertex
///    corrections (eq. 4.12) with this model's blended matrices.
/// The rest pose's transforms stay at the identity. That fixes the gauge (otherwise the
/// rest positions and every transform could turn together), makes the glTF bind pose show
/// the rest pose, and its term ‖v_j − y_j^rest‖² keeps the corrected rest positions near
/// the original ones (and block 3's 3×3 matrix invertible).
/// Start: the thesis's segmentation-driven proxy bones (skinning_weights.h), transforms at
/// the identity; the first rigid block runs more Procrustes sweeps, which move each bone
/// onto the motion of its own segment. Bone re-seeding: a segmentation can leave bones on
/// slivers of a few vertices that lower the error little; during the first iterations a
/// bone whose support Σ_j w_bj is below a fraction of the average is moved to where the
/// error is largest (it takes a ball of vertices around the worst vertex; the vertices it
/// leaves go to their other bones or a neighbour's), as SSDR re-initialises
/// insignificant bones. Iterations stop when one lowers E by less than `minRelativeGain`
/// or after `maxIterations`; a last transform block then fits the transforms to the final
/// weights and rest positions. Rest-to-pose by construction: nothing accumulates from pose
/// to pose (the pose-to-pose chain's drift cannot occur).

#include "core/animation/vertex_graph.h"
#include "core/skinning/skinning_affine.h"
#include "core/skinning/skinning_model.h"
#include "core/skinning/skinning_reconstruction.h"
#include "core/util/task_control.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace trimlab {

struct SkinningDecompositionOptions {
    bool rigidJoints = true;       ///< rigid transforms (the glTF skin) or affine ones
    unsigned maxIterations = 100;  ///< transform + weight + rest updates
    double minRelativeGain = 3e-4; ///< stop when an iteration lowers E by less than this fraction
    bool updateWeights = true;     ///< block 2 (the weight corrections)
    /// Influences per vertex the weight block may use: 4 (kDefaultInfluences) plays in every
    /// engine; up to 8 (kMaxInfluences) are exported as JOINTS_1/WEIGHTS_1 and lower the
    /// error where parts blend over wide regions (cloth), but not every viewer reads them.
    std::size_t maxInfluences = kDefaultInfluences;
    bool updateRestPositions = true; ///< block 3 (the vertex corrections)
    /// During the first `reseedIterations` iterations (with weight updates), bones whose
    /// support is below `minBoneSupport` × (#V / B) are re-seeded (file comment).
    unsigned reseedIterations = 10;
    double minBoneSupport = 0.5;
    unsigned firstJointSweeps = 30; ///< rigid: Procrustes sweeps of the first block (from the identity)
    unsigned jointSweeps = 1;       ///< rigid: sweeps of later blocks (warm-started)
    unsigned finalJointSweeps = 8;  ///< rigid: sweeps of the transform block after the last iteration
    unsigned threads = 0;           ///< 0 = hardware; results do not depend on it
};

struct SkinningDecomposition {
    std::vector<glm::dvec3> restPositions;        ///< #V, the bind pose
    SkinningWeights weights;                      ///< #V, convex, ≤ maxInfluences influences
    std::vector<std::vector<Affine3>> transforms; ///< #P × B rest-to-pose (rigid when rigidJoints)
    /// E_RMS (1000·√(E / 3nk), skinning_error.h) after each iteration and after the last
    /// transform block; back() is the result's.
    std::vector<double> eRmsHistory;
    double firstFitERms = 0.0;     ///< after the first transform block, before any weight or rest update
    std::size_t iterations = 0;    ///< iterations run (the last transform block not counted)
    std::size_t reseededBones = 0; ///< bone re-seedings done (a bone can be moved more than once)
};

/// Runs the decomposition on `poses` (#P × #V, the original animation; `restPose` < #P)
/// from `restPositions` (#V) and `weights` (#V, convex; B = weights.boneCount). `graph`:
/// the mesh's vertex graph (weight candidates, re-seeding balls). Progress stage "fit",
/// one item per iteration; cancellable between and inside iterations (OperationCancelled).
/// Throws std::invalid_argument when sizes disagree or there are no poses.
[[nodiscard]] SkinningDecomposition decomposeSkinning(const std::vector<PosePositions>& poses, std::size_t restPose,
                                                      std::vector<glm::dvec3> restPositions, SkinningWeights weights,
                                                      const VertexGraph& graph,
                                                      const SkinningDecompositionOptions& options = {},
                                                      const TaskControl& control = {});

/// The decomposition as a SkinningModel: LBS, rest-to-pose, with its transforms (for rigid
/// joints reconstructPoses then plays exactly what a glTF skin plays).
[[nodiscard]] SkinningModel decomposedSkinningModel(const SkinningDecomposition& decomposition, std::size_t restPose,
                                                    std::vector<glm::uvec3> triangles);

} // namespace trimlab
