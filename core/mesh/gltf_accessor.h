#pragma once
/// \file
/// Validated reading of glTF 2.0 accessors (positions, indices, and any numbers: animation
/// keyframes, morph weights, skin joints and matrices) from a tinygltf model.
/// Every byte range is checked against its buffer view and buffer before it is read.
/// Internal to the glTF reader; includes no tinygltf header.

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace trimlab {

/// Who is reading, for error messages: the file's display name and the element being
/// read, e.g. "mesh 0 primitive 1".
struct GltfReadContext {
    const std::string& displayName;
    std::string element;
};

/// Reads accessor `accessor` as #count positions. It must be a VEC3 of FLOAT (or, with
/// KHR_mesh_quantization, of a normalized or plain integer type). Sparse accessors and
/// accessors without a buffer view (zeros) are supported.
/// Throws MeshLoadError naming the accessor for: an index out of range, a wrong type, a
/// byte range outside its buffer view or buffer, a bad stride, or a non-finite value.
[[nodiscard]] std::vector<glm::vec3> readGltfPositions(const tinygltf::Model& model, int accessor,
                                                       const GltfReadContext& context);

/// Reads accessor `accessor` as #count × n numbers (row i holds element i; n = 1 for
/// SCALAR, 2–4 for VECn, 4/9/16 for MATn in glTF's column-major order). `type` is a
/// TINYGLTF_TYPE_* constant the accessor must have. Any component type is accepted for
/// scalars and vectors (normalized integers map to [0, 1] or [−1, 1], as for animation
/// rotations, morph weights and skin weights); matrices must be FLOAT. Sparse accessors
/// and accessors without a buffer view (zeros) are supported.
/// Throws MeshLoadError naming the accessor for the layout problems readGltfPositions
/// reports, a wrong type, and non-finite values.
[[nodiscard]] std::vector<double> readGltfNumbers(const tinygltf::Model& model, int accessor, int type,
                                                  const GltfReadContext& context);

/// Reads accessor `accessor` as vertex indices: a SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT
/// or UNSIGNED_INT, each less than `vertexCount`. Throws MeshLoadError naming the accessor
/// and the element for the same layout problems as readGltfPositions and for
/// out-of-range indices.
[[nodiscard]] std::vector<std::uint32_t> readGltfIndices(const tinygltf::Model& model, int accessor,
                                                         std::size_t vertexCount, const GltfReadContext& context);

} // namespace trimlab
