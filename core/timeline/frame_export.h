#pragma once
/// \file
/// Exporting the frames of a timeline for other tools: a numbered OBJ sequence (which
/// TrimLab's own mesh-sequence loader reads back) and one glTF 2.0 file whose morph-target
/// animation steps through the frames.

#include "core/timeline/timeline.h"

#include <filesystem>
#include <string>
#include <vector>

namespace trimlab::timeline {

/// Writes frame f of `timeline` as `<directory>/<baseName>_NNNN.obj` (f zero-padded to 4
/// digits, more when needed) for every frame 0 … frameCount()−1, creating `directory`
/// when missing. Each file has the base mesh's triangles and frame f's positions as
/// `v x y z` lines ("%.9g": enough digits to read back the same float) and 1-based
/// `f a b c` lines, in the base mesh's vertex order. Returns the paths written, in frame
/// order. Throws std::invalid_argument for an empty or path-like `baseName`, and
/// std::runtime_error naming the file when one cannot be written.
std::vector<std::filesystem::path> exportObjSequence(const Timeline& timeline, const std::filesystem::path& directory,
                                                     const std::string& baseName);

/// The morph-target animation of `timeline` as glTF 2.0: one mesh whose POSITION is the
/// base mesh (with min/max) and, for every frame f >= 1, morph target f−1 holding the
/// displacement positionsAt(f) − base as a sparse accessor (only vertices that differ
/// from the base; zeros elsewhere), with min/max; mesh.weights all zero; and animation
/// "frames" whose STEP-interpolated weights channel has keyframe f at time f / fps with
/// target f−1 at weight 1 and all others 0 (frame 0: all zero). A timeline without
/// strokes gives the mesh alone (no targets, no animation). `binary` selects .glb bytes
/// (true) or .gltf JSON with the buffer embedded as a data URI.
/// Throws std::invalid_argument for fps <= 0 or not finite, or a base mesh without
/// triangles; std::runtime_error when tinygltf cannot serialise the model.
[[nodiscard]] std::string morphGltf(const Timeline& timeline, double fps, bool binary);

/// Writes morphGltf to `path`, binary when the extension is ".glb" (case-insensitive),
/// otherwise .gltf JSON. std::runtime_error naming the file when it cannot be written.
void exportMorphGltf(const Timeline& timeline, const std::filesystem::path& path, double fps = 24.0);

} // namespace trimlab::timeline
