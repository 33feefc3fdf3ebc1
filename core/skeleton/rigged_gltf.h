#pragma once
/// \file
/// Exporting a rigged mesh as glTF 2.0 (Berenguer & Moreno III.F, which writes FBX; glTF
/// is the open format every engine and DCC tool reads): the rest mesh, the skeleton as a
/// node hierarchy and a skin with the bone-heat weights.
///
/// Layout:
/// - Node 0 "mesh": the mesh (no transform; glTF ignores a skinned mesh node's transform),
///   skin 0. Node 1 "root": the root joint, translated to the rig's root joint. Nodes
///   2 … B+1: one joint node per bone b, named by bone_names.h (`spine_1`, `leg_L_2`, …),
///   placed at the bone's head, child of its
///   parent bone's node (or of "root" for a bone that starts at the root joint). The scene
///   holds nodes 0 and 1. The skin's joints are nodes 2 … B+1 in bone order, then node 1,
///   so JOINTS_0 value b means bone b and the root joint (index B) binds no vertex;
///   skin.skeleton = 1. Every ancestor of a joint is a joint, so the rest pose is the
///   bind pose and a client that rebuilds bones from the skin (Blender) opens the rig in
///   its rest position, with one root bone and no pose on it.
/// - Orientation: joint node b is turned so that its local +Y axis points from the head
///   to the tail (the shortest rotation from +Y; a bone pointing along −Y turns by π about
///   +X; a zero-length bone keeps the identity). The paper defines a bone "as a vector
///   with an origin and a direction" with a canonical bone along one axis, and Blender and
///   most glTF tools draw a joint as a bone along its node's +Y: with this orientation
///   the imported bones point at their tails and a rotation about local Y twists a limb
///   about its own axis. The inverse bind matrices cancel the orientation, so it changes
///   nothing about the skinned mesh.
/// - Matrices (eq. 15–16): the world matrix of joint b at rest is M_W(b) = T(head)·R_b;
///   the file stores only local transforms, M_L(b) = M_W(parent)⁻¹·M_W(b), as translation
///   and rotation (scale 1). The inverse bind matrix of joint b is the inverse of the
///   world matrix composed from the written (float) local transforms, so at the bind pose
///   every joint matrix is the identity up to float rounding of one matrix.
/// - Mesh: POSITION (min/max), NORMAL (angle-weighted, unit; a vertex without a usable
///   normal gets +Z), JOINTS_0 (unsigned short) and WEIGHTS_0 (float) from BoneWeights,
///   UNSIGNED_INT indices. Weights are written so that the Khronos validator's check
///   holds: they are divided by their sum, and the float sum of the non-zero weights,
///   accumulated in float as the validator does, is 1 within 1e-7 (the largest weight
///   absorbs the rounding); unused slots have joint 0 and weight 0, and an influence whose
///   float weight is 0 is written as unused.
/// - Optional pose (RiggedGltfOptions::pose): an animation "pose" with keyframes at 0 s
///   (rest) and 1 s (the pose): every bone joint's rotation and the root joint's
///   translation, LINEAR. A glTF viewer then shows at 1 s exactly the LBS of
///   skeleton_pose.h with those weights (joint matrix = bone motion).

#include "core/mesh/triangle_mesh.h"
#include "core/skeleton/bone_heat_weights.h"
#include "core/skeleton/skeleton.h"
#include "core/skeleton/skeleton_pose.h"

#include <filesystem>
#include <string>

namespace trimlab {

struct RiggedGltfOptions {
    const SkeletonPose* pose = nullptr; ///< adds the two-keyframe animation "pose" when set
};

/// The file's bytes: binary glTF (.glb) when `binary`, else JSON with the buffer embedded
/// as base64. Throws std::invalid_argument when the mesh has no triangles, a non-finite
/// position or a triangle index ≥ #V; the rig is inconsistent (requireValidRig) or has
/// no bone or more than 65535; the weights do not have one entry per vertex or name a
/// bone outside the rig; the pose does not fit the rig (boneMotions). std::runtime_error
/// when tinygltf cannot serialise the model.
[[nodiscard]] std::string riggedGltf(const TriangleMesh& mesh, const SkeletonRig& rig, const BoneWeights& weights,
                                     bool binary, const RiggedGltfOptions& options = {});

/// Writes riggedGltf to `path` atomically, binary when it ends in .glb (any case).
/// Throws as riggedGltf, and std::runtime_error naming the file when it cannot be written.
void exportRiggedGltf(const TriangleMesh& mesh, const SkeletonRig& rig, const BoneWeights& weights,
                      const std::filesystem::path& path, const RiggedGltfOptions& options = {});

/// Joint orientation used by the export: the shortest rotation taking +Y to the direction
/// from `head` to `tail` (identity for a zero-length or non-finite bone).
[[nodiscard]] glm::dquat boneOrientation(const glm::dvec3& head, const glm::dvec3& tail);

} // namespace trimlab
