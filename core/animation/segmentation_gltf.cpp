#include "core/animation/segmentation_gltf.h"

#include "core/io/gltf_builder.h"
#include "core/io/atomic_write.h"

#include <tiny_gltf.h>

#include <glm/common.hpp>

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace trimlab {

namespace {

int addPositions(tinygltf::Model& model, const TriangleMesh& mesh)
{
    return io::addGltfVec3Accessor(model, mesh.positions, TINYGLTF_TARGET_ARRAY_BUFFER, true);
}

tinygltf::Model buildModel(const TriangleMesh& mesh, const VertexLabeling& segmentation,
                           std::span<const WheelColor> colors)
{
    tinygltf::Model model;
    model.asset.generator = "TrimLab segmentation export";
    model.asset.extras =
        tinygltf::Value(tinygltf::Value::Object{{"segment_count", tinygltf::Value(int(segmentation.count))}});
    model.buffers.emplace_back();
    tinygltf::Primitive primitive;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.attributes["POSITION"] = addPositions(model, mesh);
    std::vector<glm::vec3> rgb;
    std::vector<float> labels;
    for (const std::uint32_t label : segmentation.labels) {
        rgb.push_back(colors[label].rgb());
        labels.push_back(float(label));
    }
    const int colorView =
        io::addGltfBufferView(model, rgb.data(), rgb.size() * sizeof(glm::vec3), TINYGLTF_TARGET_ARRAY_BUFFER);
    primitive.attributes["COLOR_0"] =
        io::addGltfAccessor(model, colorView, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, rgb.size());
    const int labelView =
        io::addGltfBufferView(model, labels.data(), labels.size() * sizeof(float), TINYGLTF_TARGET_ARRAY_BUFFER);
    primitive.attributes["_SEGMENT"] =
        io::addGltfAccessor(model, labelView, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_SCALAR, labels.size());
    primitive.indices = io::addGltfTriangleIndices(model, mesh.triangles);
    io::addGltfSingleMeshScene(model, primitive, "segmentation");
    return model;
}

} // namespace

std::string segmentationGltf(const TriangleMesh& mesh, const VertexLabeling& segmentation,
                             std::span<const WheelColor> colors)
{
    if (segmentation.labels.size() != mesh.positions.size() || mesh.positions.empty())
        throw std::invalid_argument("segmentationGltf: " + std::to_string(segmentation.labels.size()) + " labels for " +
                                    std::to_string(mesh.positions.size()) + " vertices");
    if (colors.size() < segmentation.count)
        throw std::invalid_argument("segmentationGltf: fewer colours than segments");
    const tinygltf::Model model = buildModel(mesh, segmentation, colors);
    std::ostringstream out;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, out, true, false))
        throw std::runtime_error("tinygltf could not serialise the segmentation");
    return out.str();
}

void writeSegmentationGltf(const std::filesystem::path& path, const TriangleMesh& mesh,
                           const VertexLabeling& segmentation, std::span<const WheelColor> colors)
{
    io::writeFileAtomically(path, segmentationGltf(mesh, segmentation, colors));
}

} // namespace trimlab
