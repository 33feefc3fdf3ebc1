#pragma once
/// \file
/// A sequence of meshes that do not share their topology (an animation trimmed pose by
/// pose: every pose's solid has its own triangles) as one glTF 2.0 file that plays it.
///
/// glTF has no visibility flag and morph targets need one topology, so each mesh gets a
/// node of its own, all children of one node "sequence", and an animation "poses" shows
/// them in turn by scale: node k has scale 1 from times[k] until times[k + 1] and 0
/// otherwise, STEP interpolation. Blender's importer turns it into object scale keys
/// with constant interpolation, and three.js and other players play it as it is. A reader
/// that does not play animations sees the first mesh only (the others rest at scale 0).

#include "core/mesh/triangle_mesh.h"

#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace trimlab {

/// One mesh of the sequence: its node's name and its geometry.
struct SequenceMesh {
    std::string name;
    TriangleMesh mesh;
};

/// Writes `meshes` (at least one) to `path` (.gltf with the buffer embedded, .glb binary),
/// mesh k shown from `secondsPerMesh`·k on, atomically. A mesh without triangles (a pose
/// whose solid is empty) is a node without a mesh: at its time nothing shows. Throws
/// std::invalid_argument for no mesh or only empty ones, another extension, a mesh with
/// a triangle index out of range or a non-finite position (naming the mesh), or
/// `secondsPerMesh` not > 0;
/// std::runtime_error naming the file when it cannot be written.
void saveMeshSequenceGltf(const std::filesystem::path& path, std::span<const SequenceMesh> meshes,
                          double secondsPerMesh, std::string_view comment = {});

} // namespace trimlab
