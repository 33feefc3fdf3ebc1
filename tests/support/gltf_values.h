#pragma once
// The float values of a glTF accessor as TrimLab writes them (one buffer view, tightly
// packed, SCALAR or VEC3), for tests that check animation keys without a player.

#include <tiny_gltf.h>

#include <cstring>
#include <vector>

namespace trimlab::test {

inline std::vector<float> gltfFloats(const tinygltf::Model& model, int index)
{
    const tinygltf::Accessor& accessor = model.accessors[std::size_t(index)];
    const tinygltf::BufferView& view = model.bufferViews[std::size_t(accessor.bufferView)];
    const std::size_t components = accessor.type == TINYGLTF_TYPE_VEC3 ? 3 : 1;
    std::vector<float> values(accessor.count * components);
    std::memcpy(values.data(),
                model.buffers[std::size_t(view.buffer)].data.data() + view.byteOffset + accessor.byteOffset,
                values.size() * sizeof(float));
    return values;
}

} // namespace trimlab::test
