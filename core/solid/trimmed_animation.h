#pragma once
/// \file
/// A mesh animation trimmed pose by pose as exact geometry: each pose's solid under a
/// static rule (and the clipping planes, cutTrimmedSolid), as `trimlab trim ANIM --poses`
/// and the window's export of an open animation write it. Each pose is trimmed on its
/// own: the dynamic rules, which remember the poses before, have no exact export.

#include "core/animation/mesh_animation.h"
#include "core/solid/trimmed_solid.h"
#include "core/trim/trim_settings.h"
#include "core/util/task_control.h"

#include <cstddef>
#include <functional>
#include <string>

namespace trimlab {

/// Called after each pose with its number and its solid, in pose order (the caller writes
/// it and lets it go, so a long animation never holds every solid at once).
using TrimmedPoseSink = std::function<void(std::size_t pose, const TrimmedSolid& solid)>;

/// The name a trimmed pose goes by in a sequence file: "pose_0007" (zero-padded to four
/// digits, so the names sort in pose order up to pose 9999).
[[nodiscard]] std::string trimmedPoseName(std::size_t pose);

/// Trims poses `first` … `last` (inclusive) of `animation` under `settings`, as many poses
/// at once as there are cores, and hands them to `each` in pose order (the solids do not
/// depend on the thread count). Progress: the stage "poses", done/total after every pose;
/// cancellation between poses (a running pose finishes first). Throws
/// std::invalid_argument when the range is empty or past the last pose, or when a pose is
/// not a closed surface (its validation's reason, naming the pose: close the holes
/// first), and as cutTrimmedSolid throws; OperationCancelled when `control` asks. When
/// poses fail, the first of them in pose order is reported, after the poses before it
/// were handed over, as a run of one pose at a time would.
void trimAnimationPoses(const MeshAnimation& animation, std::size_t first, std::size_t last,
                        const TrimSettings& settings, const TrimmedPoseSink& each, const TaskControl& control = {});

} // namespace trimlab
