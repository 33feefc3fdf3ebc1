#pragma once
/// \file
/// Exporting a skinned approximation (SkinningModel) as glTF 2.0, so that any engine or
/// viewer can play it: a skin with one joint per bone, or per-pose morph targets.
///
/// The skin export (SkinExportKind::RigidTransforms / RigidApproximation):
/// - Nodes: 0 the mesh node (a scene root, no transform, `skin` 0); 1 the skeleton root
///   "skeleton" (identity); 2 … B+1 the joints "bone_b", children of the skeleton root (a
///   flat hierarchy: no bone is parented to another).
/// - The mesh: POSITION = the model's rest positions (with min/max), JOINTS_0 (VEC4
///   unsigned short) and WEIGHTS_0 (VEC4 float) = the model's first 4 influences, sorted
///   by decreasing weight, unused slots joint 0 / weight 0, and the written floats summing
///   to 1 (the largest weight takes the float rounding), UNSIGNED_INT indices. A model
///   with more than 4 influences somewhere (up to 8) adds JOINTS_1/WEIGHTS_1 for the
///   influences 5–8 of every vertex.
/// - Bind convention: joint b rests at its pivot c_b (the weighted centroid of its
///   vertices, skinning_gltf_joints.h) with no rotation, and its inverse bind matrix is
///   the translation by −c_b. So at the bind pose every joint matrix is the identity and
///   the mesh is its rest positions; a joint rotates about its own part of the mesh (which
///   is also what makes keyframe interpolation between poses look natural).
/// - Animation "skinning": pose t is a keyframe at time t/fps; each joint has a
///   translation and a rotation channel (LINEAR by default, or STEP), the node's
///   translation being R·c_b + t and its rotation R for the rigid motion x ↦ R x + t of
///   rigidJointAnimation. Scale is never animated (it stays 1). Consecutive rotations
///   are sign-aligned so that LINEAR interpolation (slerp) takes the short way.
/// - What a viewer then shows at pose t is Σ_i w_i (R_i v + t_i): LBS of the rigid joint
///   matrices. That is exact for rigid data, but it is neither the DQS blend of a DQS
///   model nor the affine blend of an LBS model. The report's `positions` are computed
///   exactly that way from the values as written (floats), so comparing them with the
///   original animation gives the E_RMS of the file itself.
///
/// Affine (LBS) fits: glTF animates each joint by translation, rotation and a scale along
/// the joint's own axes; the shear and rotated non-uniform scale of a general affine bone
/// matrix cannot be expressed. Such a model is exported as its best rigid approximation
/// (RigidApproximation: started from the closest rotation by polar decomposition, then
/// the rigid joints refitted to the target positions; skinning_gltf_joints.h), whose
/// error is larger than the fit's; or, with `morphTargets`, as morph targets that
/// reproduce the fit exactly.
///
/// The morph-target export (SkinExportKind::MorphTargets): the rest positions as the base
/// mesh, one morph target per pose (displacement of pose t from the rest positions) and a
/// STEP "weights" channel that selects target t at time t/fps — exact up to float
/// rounding, but #P × #V displacements instead of #P × B transforms.

#include "core/skinning/skinning_model.h"
#include "core/skinning/skinning_reconstruction.h"

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace trimlab {

enum class SkinExportKind {
    RigidTransforms,    ///< a DQS model or a rigid decomposition: its rigid bone motions as joint TRS channels
    RigidApproximation, ///< an LBS (affine) model: the best rigid approximation per bone and pose
    MorphTargets,       ///< one morph target per pose (exact)
};

/// "rigid transforms", "rigid approximation of an affine fit", "morph targets".
[[nodiscard]] std::string_view skinExportKindName(SkinExportKind kind);

struct SkinExportOptions {
    bool morphTargets = false;      ///< export morph targets instead of a skin
    bool stepInterpolation = false; ///< STEP keyframes instead of LINEAR (skin export)
    /// The positions the joint translations are fitted to (#P × #V): normally the original
    /// animation. Null: the model's own reconstruction (reconstructPoses).
    const std::vector<PosePositions>* target = nullptr;
};

/// What was written.
struct ExportedSkin {
    SkinExportKind kind = SkinExportKind::RigidTransforms;
    std::size_t joints = 0; ///< B for a skin, 0 for morph targets
    /// #P × #V positions the file reproduces at the keyframe times, computed as a glTF
    /// viewer does (see above): measureSkinningError(original, positions) is the E_RMS of
    /// the export.
    std::vector<PosePositions> positions;
};

/// The file's bytes and the report.
struct SkinnedGltf {
    std::string bytes;
    ExportedSkin report;
};

/// Builds the glTF: binary (.glb) when `binary`, else JSON with the buffer embedded as
/// base64. Throws std::invalid_argument for a model without poses, vertices or
/// triangles, inconsistent sizes (weights, transforms, target), more than 65535 bones,
/// or an fps that is not finite and > 0; std::runtime_error when tinygltf cannot
/// serialise the model.
[[nodiscard]] SkinnedGltf skinnedGltf(const SkinningModel& model, double fps, bool binary,
                                      const SkinExportOptions& options = {});

/// Writes skinnedGltf to `path` (binary when it ends in .glb, any case) atomically.
/// Throws as skinnedGltf, and std::runtime_error naming the file when it cannot be written.
ExportedSkin exportSkinnedGltf(const SkinningModel& model, const std::filesystem::path& path, double fps,
                               const SkinExportOptions& options = {});

} // namespace trimlab
