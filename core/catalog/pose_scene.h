#pragma once
/// \file
/// One pose of a mesh animation as a scene of one object, validated as a loaded mesh is:
/// what the window shows for an opened animation's rest pose, what `render --pose` draws
/// and what `trim --poses` exports, built once.

#include "core/animation/mesh_animation.h"
#include "core/catalog/scene_source.h"

#include <cstddef>
#include <string>

namespace trimlab {

/// Pose `pose` (< animation.poseCount()) as an object named `objectName`; the scene's
/// display name is `displayName` and its source `source`.
[[nodiscard]] LoadedScene animationPoseScene(const MeshAnimation& animation, std::size_t pose,
                                             const std::string& objectName, std::string displayName,
                                             std::string source = {});

} // namespace trimlab
