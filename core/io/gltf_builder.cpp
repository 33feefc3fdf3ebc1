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

int addGltfTriangleIndices(tinygltf::Model& model, const std::vector<glm::uvec3>& triangles)
{
    const int view = addGltfBufferView(model, triangles.data(), triangles.size() * sizeof(glm::uvec3),
                                       TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    return addGltfAccessor(model, view, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                           3 * triangles.size());
}

int addGltfSingleMeshScene(tinygltf::Model& model, const tinygltf::Primitive& primitive, const std::string& name,
                           int skin)
{
    tinygltf::Mesh mesh;
    mesh.name = name;
    mesh.primitives.push_back(primitive);
    model.meshes.push_back(mesh);
    tinygltf::Node node;
    node.name = name;
    node.mesh = int(model.meshes.size() - 1);
    node.skin = skin;
    model.nodes.push_back(node);
    const int nodeIndex = int(model.nodes.size() - 1);
    tinygltf::Scene scene;
    scene.nodes = {nodeIndex};
    model.scenes.push_back(scene);
    model.defaultScene = int(model.scenes.size() - 1);
    return nodeIndex;
}

} // namespace trimlab
