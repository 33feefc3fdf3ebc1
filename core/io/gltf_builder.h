#pragma once
/// \file
/// Small helpers for the glTF writers (segmentation export, morph-target export):
/// append raw data to buffer 0 as a buffer view, and describe it with an accessor.

#include <tiny_gltf.h>

#include <cstddef>

namespace trimlab {

/// Appends `size` bytes to model.buffers[0] (4-byte aligned) as a new buffer view and
/// returns its index. `target` 0 leaves the view without a target (animation data,
/// sparse accessor parts).
int addGltfBufferView(tinygltf::Model& model, const void* bytes, std::size_t size, int target);

/// Adds an accessor over buffer view `view` (−1: none, e.g. all-sparse) and returns its index.
int addGltfAccessor(tinygltf::Model& model, int view, int componentType, int type, std::size_t count);

} // namespace trimlab
