#pragma once
/// \file
/// An opened mesh animation as the window shows it: the poses (shared, read-only, with
/// the segmentation jobs that read them), the rest pose as a one-object scene with its
/// validation report (so the trim controls and the viewport treat it like an opened
/// mesh), and the bounds of every pose (so no pose leaves the camera's depth range).

#include "core/animation/mesh_animation.h"
#include "core/skinning/skinning_model.h"
#include "core/util/task_control.h"
#include "core/catalog/scene_source.h"
#include "core/trim/hole_closing.h"

#include <memory>
#include <string>

namespace trimlab::ui {

struct LoadedAnimation {
    std::shared_ptr<const MeshAnimation> animation;
    /// The rest pose; `source` is the animation's source, `displayName` its folder or
    /// file name, one object named like it.
    std::shared_ptr<const LoadedScene> restScene;
    Bounds bounds; ///< of every position of every pose
    /// The skin a glTF file was posed with, as the GPU skinning path plays it
    /// (core/skinning/file_skin_model.h); nullptr for sequences, morphs and files whose
    /// skin the GPU path cannot blend (the viewport then uploads each sampled pose).
    std::shared_ptr<const SkinningModel> fileSkin;
    double loadMs = 0.0; ///< wall-clock time of loadAnimation (for the export's times)
};

/// Loads `source` (a folder, a numbered or wildcard pattern, or a .gltf/.glb file) with
/// loadAnimation (rest pose 0) and prepares the rest scene and bounds. For a worker
/// thread: throws what loadAnimation throws (MeshLoadError naming the file,
/// OperationCancelled).
[[nodiscard]] LoadedAnimation loadAnimationForDisplay(const std::string& source, const TaskControl& control);

/// `loaded` with the holes of every pose closed (closeAnimationHoles), and into `closing`
/// what was closed: its rest scene and bounds redone, no file skin (the skin binds the
/// open mesh's vertices only, so the viewport uploads each pose). Throws
/// std::invalid_argument as closeAnimationHoles does (a boundary that forms no loops).
[[nodiscard]] LoadedAnimation withHolesClosed(const LoadedAnimation& loaded, HoleClosing* closing = nullptr);

} // namespace trimlab::ui
