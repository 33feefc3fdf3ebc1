#pragma once
/// \file
/// The one entry point for loading a mesh animation: a mesh sequence (folder or
/// pattern) or a glTF file, with a chosen rest pose.

#include "core/animation/gltf_animation.h"
#include "core/animation/mesh_animation.h"
#include "core/trim/hole_closing.h"
#include "core/util/task_control.h"

#include <cstddef>
#include <string>

namespace trimlab {

struct AnimationLoadOptions {
    GltfAnimationOptions gltf; ///< for glTF sources only
    std::size_t restPose = 0;  ///< index of the rest pose in the loaded poses
    unsigned threads = 0;      ///< file loading threads (0 = hardware concurrency)
    /// Close the holes of every pose (closeAnimationHoles) after loading.
    bool closeHoles = false;
};

/// Loads `source`: a .gltf/.glb(.gz) file (gltf_animation.h), otherwise a folder or a
/// numbered or wildcard pattern (sequence_files.h) loaded by loadMeshSequence, and sets
/// the rest pose; with `options.closeHoles` closes the holes and says in `closing` (when
/// given) what was closed and where a fan crosses a pose (closed_animation.h). Throws
/// MeshLoadError naming the source or the offending file, also when `options.restPose` is
/// not a pose index ("the rest pose 40 does not exist; the animation has 35 poses (0 to
/// 34)"), or when a boundary to close does not form loops; OperationCancelled when asked
/// to stop.
[[nodiscard]] MeshAnimation loadAnimation(const std::string& source, const AnimationLoadOptions& options = {},
                                          const TaskControl& control = {}, HoleClosing* closing = nullptr);

} // namespace trimlab
