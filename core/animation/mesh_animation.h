#pragma once
/// \file
/// A mesh animation (thesis chapter 3: "mesh animation" A, a sequence of poses p_0 … p_k
/// of one mesh with constant connectivity): the shared triangles, one position array per
/// pose, and which pose is the rest pose.

#include "core/animation/animation_skin.h"
#include "core/mesh/triangle_mesh.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace trimlab {

/// Every pose has the same #V vertices and the same #F triangles.
/// - `triangles`: #F×3 vertex indices, shared by all poses, counter-clockwise seen from
///   outside (as TriangleMesh).
/// - `poses`: #P arrays of #V positions each (object space, the file's units).
/// - `poseNames`: #P display names (the file name of a sequence frame, or
///   "animation NAME t=0.500 s" for a sampled glTF pose); used in messages and exports.
/// - `poseTimes`: #P times in seconds for sampled glTF animations; empty for file
///   sequences (the frame number is the time).
/// - `restPose`: the pose deformation gradients are measured against (ReferenceMode::Rest)
///   and whose geometry gives areas and the exported mesh; < #P.
struct MeshAnimation {
    std::vector<glm::uvec3> triangles;
    std::vector<std::vector<glm::vec3>> poses;
    std::vector<std::string> poseNames;
    std::vector<double> poseTimes;
    std::size_t restPose = 0;
    /// The glTF skin that posed the poses (animation_skin.h), or nullptr: file sequences,
    /// morphs, several skins. Its jointMatrices has one entry per pose as loaded; code
    /// that drops or reorders poses resets it, and users check the counts.
    std::shared_ptr<const AnimationSkin> skin;

    [[nodiscard]] std::size_t poseCount() const { return poses.size(); }
    [[nodiscard]] std::size_t vertexCount() const { return poses.empty() ? 0 : poses.front().size(); }
    [[nodiscard]] std::size_t triangleCount() const { return triangles.size(); }
    /// Pose `index` as a stand-alone mesh (copies the positions and the triangles).
    [[nodiscard]] TriangleMesh poseMesh(std::size_t index) const;
};

/// Throws std::invalid_argument naming the first problem when `animation` is not
/// well-formed: no poses, no triangles, poses of different sizes, an index ≥ #V, a
/// `restPose` ≥ #P, or name/time arrays of the wrong length. Loaders always return
/// well-formed animations; this guards animations built in code.
void requireWellFormed(const MeshAnimation& animation);

} // namespace trimlab
