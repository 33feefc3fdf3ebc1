#pragma once
/// \file
/// Loading a mesh sequence (one mesh file per pose) into a MeshAnimation.

#include "core/animation/mesh_animation.h"
#include "core/util/task_control.h"

#include <filesystem>
#include <vector>

namespace trimlab {

/// Loads every file with loadMesh (mesh_io.h: OBJ, PLY, OFF, STL, each optionally .gz;
/// polygons are triangulated) on up to `threads` threads (0 = hardware concurrency) and
/// returns them as poses in the given order, named by their file names, rest pose 0.
/// The first file fixes the vertex count and the triangles; every other file must match
/// them (pose_topology.h: re-triangulated polygons are accepted and take the first
/// file's triangles).
/// Throws MeshLoadError for the first file (in list order) that cannot be loaded or does
/// not match, naming it; std::invalid_argument for an empty list; OperationCancelled
/// when `control` asks to stop. Progress stage: "load", one item per file after the first.
[[nodiscard]] MeshAnimation loadMeshSequence(const std::vector<std::filesystem::path>& files,
                                             const TaskControl& control = {}, unsigned threads = 0);

} // namespace trimlab
