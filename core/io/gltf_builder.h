#pragma once
/// \file
/// Small helpers for the glTF writers (segmentation, morph-target, skinning and rig
/// exports): append raw data to buffer 0 as a buffer view, describe it with an accessor,
/// and make the one mesh they all write the scene.

#include <tiny_gltf.h>

#include <glm/vec3.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace trimlab {

/// Appends `size` bytes to model.buffers[0] (4-byte aligned) as a new buffer view and
/// returns its index. `target` 0 leaves the view without a target (animation data,
/// sparse accessor parts).
int addGltfBufferView(tinygltf::Model& model, const void* bytes, std::size_t size, int target);

/// Adds an accessor over buffer view `view` (−1: none, e.g. all-sparse) and returns its index.
int addGltfAccessor(tinygltf::Model& model, int view, int componentType, int type, std::size_t count);

/// The triangles (#F×3 vertex indices) as an element-array view and an unsigned-int
/// scalar accessor of 3·#F indices; returns the accessor for Primitive::indices.
int addGltfTriangleIndices(tinygltf::Model& model, const std::vector<glm::uvec3>& triangles);

/// Appends a mesh `name` holding `primitive`, a node `name` showing it (with skin `skin`,
/// −1 for none), and a scene holding that node, which becomes the default scene.
/// Returns the node's index.
int addGltfSingleMeshScene(tinygltf::Model& model, const tinygltf::Primitive& primitive, const std::string& name,
                           int skin = -1);

} // namespace trimlab
