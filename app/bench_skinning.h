#pragma once
/// \file
/// The animation scenes of `trimlab bench`: a skinned pose played on the CPU (one skinning
/// step, then the float conversion, normals and upload of GpuScene::updatePositions)
/// against the GPU (render/frame/gpu_skinning.h: bone transforms uploaded, skinning and
/// normals in compute passes), side by side in one run.
/// - skinning:samba — the first 40 poses of samba (9,971 vertices);
/// - skinning:elephant-gallop — all 48 poses (42,321 vertices).
/// Each is fitted with 20 bones (core/skinning/seed_bones.h) by LBS and DQS, pose-to-pose
/// and rest-to-pose; every pose of every model is timed in playback order (CPU and GPU
/// taking turns pose by pose, so a busy machine slows both alike), and the GPU's positions
/// are read back once per pose and compared with the CPU's. The shared data folder holds
/// the animations; a missing one skips its scene.

#include "render/trim_renderer.h"

#include "core/animation/mesh_animation.h"

#include <QString>
#include <QStringList>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace trimlab::app {

/// The largest deviation of GPU-skinned positions from the CPU's the bench accepts, as a
/// fraction of the diagonal (render.gpu_skinning's threshold).
inline constexpr double kSkinningDeviationLimit = 1e-5;

/// One skinned model of one animation, timed.
struct SkinningBenchRow {
    QString animation;
    std::size_t vertices = 0;
    std::size_t triangles = 0;
    std::size_t bones = 0;
    std::size_t poses = 0;
    QString method;           ///< "LBS" or "DQS"
    QString chain;            ///< "pose-to-pose" or "rest-to-pose"
    double cpuSkinMs = 0.0;   ///< median per pose: the skinning step
    double cpuUploadMs = 0.0; ///< median per pose: floats, normals, upload (glFinish'ed)
    double gpuMs = 0.0;       ///< median per pose: GpuSkinning::skinPose (glFinish'ed)
    /// Largest distance of a GPU-skinned vertex from the CPU's, over every pose, as a
    /// fraction of the rest pose's bounding-box diagonal.
    double largestDeviation = 0.0;
};

[[nodiscard]] std::vector<std::string> skinningBenchSceneNames();
/// The names joined by ", ", for help texts.
[[nodiscard]] std::string skinningBenchSceneNamesText();
[[nodiscard]] bool isSkinningBenchScene(const std::string& name);

/// The animation of scene `name` from `dataDirectory`; nullopt with the reason in
/// `skipReason` when its files are missing. Throws what loadAnimation throws.
[[nodiscard]] std::optional<MeshAnimation> loadSkinningBenchAnimation(const std::string& name,
                                                                      const std::filesystem::path& dataDirectory,
                                                                      std::string* skipReason);

/// Fits the four models of `animation` and times them (`rounds` rounds of playback after
/// one that compiles the GPU's code). `renderer`'s context must be current.
[[nodiscard]] std::vector<SkinningBenchRow>
measureSkinning(render::TrimRenderer& renderer, const MeshAnimation& animation, const QString& name, int rounds);

/// The table of `rows`, one line each, with the CPU/GPU ratio.
[[nodiscard]] QStringList skinningTableLines(const std::vector<SkinningBenchRow>& rows);

} // namespace trimlab::app
