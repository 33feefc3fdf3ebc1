#pragma once
/// \file
/// Loading a glTF 2.0 animation (morph targets, skinning, animated node transforms) as a
/// mesh animation: the scene's triangle meshes sampled at the animation's keyframe times
/// or at a fixed frame rate.

#include "core/animation/mesh_animation.h"
#include "core/util/task_control.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace trimlab {

struct GltfAnimationOptions {
    /// Which of the file's animations to sample (0 = the first).
    int animation = 0;
    /// Frames per second; 0 samples at every keyframe time of every channel (the union,
    /// sorted). With fps > 0 the poses are at t₀ + i/fps for t₀ + i/fps ≤ t₁, where t₀,
    /// t₁ are the first and last keyframe times.
    double fps = 0.0;
};

/// The most poses a glTF animation may be sampled into.
inline constexpr std::size_t kMaxSampledPoses = 100000;

/// Loads `path` (.gltf or .glb, optionally .gz; external buffers relative to its
/// folder) and samples animation `options.animation`. Each pose is the whole default
/// scene (gltf_animated_geometry.h): morph targets blended with the animated weights,
/// skinned primitives posed by linear blend skinning with the skin's joints, weights and
/// inverse bind matrices, other primitives moved by their node's animated world matrix.
/// Vertices split at seams are welded where they coincide in every pose (pose_welding.h).
/// Pose names read "NAME t=0.250 s"; poseTimes holds the times; rest pose 0.
/// Throws MeshLoadError naming the file for every reading problem (gltf_document.h,
/// gltf_accessor.h, gltf_animation_clip.h, gltf_animated_geometry.h), a negative or
/// non-finite fps, more than kMaxSampledPoses poses, and non-finite posed positions;
/// OperationCancelled when `control` asks to stop (stage "load", one item per pose).
[[nodiscard]] MeshAnimation loadGltfAnimation(const std::filesystem::path& path,
                                              const GltfAnimationOptions& options = {},
                                              const TaskControl& control = {});

/// The same for glTF data in memory (possibly gzip-compressed); external buffers are
/// read relative to `baseDir` (empty: refused). `displayName` names the data in errors.
[[nodiscard]] MeshAnimation readGltfAnimation(std::string_view bytes, const std::string& displayName,
                                              const std::filesystem::path& baseDir,
                                              const GltfAnimationOptions& options = {},
                                              const TaskControl& control = {});

} // namespace trimlab
