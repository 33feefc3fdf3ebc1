#include "io/gltf_builder.h"

namespace trimlab {

int addGltfBufferView(tinygltf::Model& model, const void* bytes, std::size_t size, int target)
{
    std::vector<unsigned char>& data = model.buffers[0].data;
    data.resize((data.size() + 3) / 4 * 4, 0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = size;
    view.target = target;
    const auto* begin = static_cast<const unsigned char*>(bytes);
    data.insert(data.end(), begin, begin + size);
    model.bufferViews.push_back(view);
    return int(model.bufferViews.size() - 1);
}

int addGltfAccessor(tinygltf::Model& model, int view, int componentType, int type, std::size_t count)
{
    tinygltf::Accessor accessor;
    accessor.bufferView = view;
    accessor.componentType = componentType;
    accessor.type = type;
    accessor.count = count;
    model.accessors.push_back(accessor);
    return int(model.accessors.size() - 1);
}

} // namespace trimlab
