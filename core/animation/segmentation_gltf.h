#pragma once
/// \file
/// Writing a segmentation as glTF 2.0 so that other tools can show and read it: the rest
/// pose as a triangle mesh with the segment label and colour of every vertex.

#include "core/animation/color_wheel.h"
#include "core/animation/vertex_graph.h"
#include "core/mesh/triangle_mesh.h"

#include <filesystem>
#include <span>
#include <string>

namespace trimlab {

/// The glTF JSON (embedded base64 buffer, so one self-contained .gltf file) of `mesh`
/// (the rest pose) with the vertex attributes
/// - POSITION (VEC3 float, with min/max),
/// - COLOR_0 (VEC3 float, linear RGB in [0, 1]: the colour of the vertex's segment),
/// - _SEGMENT (SCALAR float holding the integer label 0 … count−1; glTF allows
///   application-specific attributes with a leading underscore but no UNSIGNED_INT
///   vertex attributes, and float is exact for labels below 2²⁴),
/// and UNSIGNED_INT indices. `asset.extras` records the segment count.
/// Throws std::invalid_argument on size mismatches and std::runtime_error when tinygltf
/// cannot serialise the model.
[[nodiscard]] std::string segmentationGltf(const TriangleMesh& mesh, const VertexLabeling& segmentation,
                                           std::span<const WheelColor> colors);

/// Writes segmentationGltf to `path`. Throws std::runtime_error naming the file when it
/// cannot be written.
void writeSegmentationGltf(const std::filesystem::path& path, const TriangleMesh& mesh,
                           const VertexLabeling& segmentation, std::span<const WheelColor> colors);

} // namespace trimlab
