#pragma once
/// \file
/// The one glTF builder of TrimLab's writers (segmentation, design-history morph targets,
/// skinned animations, rigs): append raw data to buffer 0 as a buffer view, describe it
/// with an accessor (exact bounds where glTF asks for them), store displacements sparsely,
/// make the one mesh they all write the scene, and animate its morph targets.

#include <tiny_gltf.h>

#include <glm/vec3.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace trimlab::io {

/// Appends `size` bytes to model.buffers[0] (4-byte aligned) as a new buffer view and
/// returns its index. `target` 0 leaves the view without a target (animation data,
/// sparse accessor parts).
int addGltfBufferView(tinygltf::Model& model, const void* bytes, std::size_t size, int target);

/// Adds an accessor over buffer view `view` (−1: none, e.g. all-sparse) and returns its index.
int addGltfAccessor(tinygltf::Model& model, int view, int componentType, int type, std::size_t count);

/// The float accessors below refuse a non-finite value with std::invalid_argument naming
/// the accessor and the element: no writer puts NaN or infinity into a glTF file.

/// Float VEC3 `values` as a new view (with `target`) and accessor; with `bounds`, the
/// exact componentwise min/max (validators compare them with the data bit for bit).
int addGltfVec3Accessor(tinygltf::Model& model, const std::vector<glm::vec3>& values, int target, bool bounds);

/// Float data of `type` (SCALAR, VEC4, MAT4, …: components per element from the type)
/// without a view target; `bounds` adds min/max for scalars.
int addGltfFloatAccessor(tinygltf::Model& model, const std::vector<float>& values, int type, bool bounds);

/// Float VEC3 `values` (#V, mostly zero: a morph target's displacements) as a sparse
/// accessor holding only the non-zero ones, with bounds over all #V values.
int addGltfSparseVec3Accessor(tinygltf::Model& model, const std::vector<glm::vec3>& values);

/// The triangles (#F×3 vertex indices) as an element-array view and an unsigned-int
/// scalar accessor of 3·#F indices; returns the accessor for Primitive::indices.
int addGltfTriangleIndices(tinygltf::Model& model, const std::vector<glm::uvec3>& triangles);

/// Appends a mesh `name` holding `primitive`, a node `name` showing it (with skin `skin`,
/// −1 for none), and a scene holding that node, which becomes the default scene.
/// Returns the node's index.
int addGltfSingleMeshScene(tinygltf::Model& model, const tinygltf::Primitive& primitive, const std::string& name,
                           int skin = -1);

/// An animation `name` of node 0's morph target weights with STEP interpolation: at
/// times[k] morph target k − `firstTargetKey` has weight 1 and every other 0; keyframes
/// before `firstTargetKey` show the base mesh. #targets = #times − firstTargetKey.
void addGltfMorphStepAnimation(tinygltf::Model& model, const std::string& name, const std::vector<float>& times,
                               std::size_t firstTargetKey);

} // namespace trimlab::io
