// exportMorphGltf / morphGltf (declared in frame_export.h): the timeline as a glTF 2.0
// morph-target animation.
#include "timeline/frame_export.h"

#include "io/gltf_builder.h"

#include <tiny_gltf.h>

#include <glm/common.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <span>
#include <sstream>
#include <stdexcept>

namespace trimlab::timeline {

namespace {

// Exact componentwise min/max: glTF validators compare them with the data bit for bit.
void setBounds(tinygltf::Accessor& accessor, std::span<const glm::vec3> values)
{
    glm::vec3 low = values.empty() ? glm::vec3(0.0f) : values.front();
    glm::vec3 high = low;
    for (const glm::vec3& v : values) {
        low = glm::min(low, v);
        high = glm::max(high, v);
    }
    accessor.minValues = {low.x, low.y, low.z};
    accessor.maxValues = {high.x, high.y, high.z};
}

int addBasePositions(tinygltf::Model& model, const std::vector<glm::vec3>& positions)
{
    const int view = addGltfBufferView(model, positions.data(), positions.size() * sizeof(glm::vec3), TINYGLTF_TARGET_ARRAY_BUFFER);
    const int accessor = addGltfAccessor(model, view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, positions.size());
    setBounds(model.accessors[std::size_t(accessor)], positions);
    return accessor;
}

// A morph target POSITION accessor: `displacement` (#V, mostly zero) stored sparsely.
int addDisplacements(tinygltf::Model& model, const std::vector<glm::vec3>& displacement)
{
    std::vector<std::uint32_t> indices;
    std::vector<glm::vec3> values;
    for (std::size_t v = 0; v < displacement.size(); ++v) {
        if (displacement[v] != glm::vec3(0.0f)) {
            indices.push_back(std::uint32_t(v));
            values.push_back(displacement[v]);
        }
    }
    // Without a buffer view the accessor is all zeros; sparse parts need >= 1 element.
    const int accessor = addGltfAccessor(model, -1, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, displacement.size());
    if (!indices.empty()) {
        const int indexView = addGltfBufferView(model, indices.data(), indices.size() * sizeof(std::uint32_t), 0);
        const int valueView = addGltfBufferView(model, values.data(), values.size() * sizeof(glm::vec3), 0);
        tinygltf::Accessor& a = model.accessors[std::size_t(accessor)];
        a.sparse.isSparse = true;
        a.sparse.count = int(indices.size());
        a.sparse.indices.bufferView = indexView;
        a.sparse.indices.byteOffset = 0;
        a.sparse.indices.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        a.sparse.values.bufferView = valueView;
        a.sparse.values.byteOffset = 0;
    }
    // min/max cover the whole accessor, zeros included unless every vertex moved.
    if (indices.size() < displacement.size())
        values.emplace_back(0.0f);
    setBounds(model.accessors[std::size_t(accessor)], values);
    return accessor;
}

int addScalars(tinygltf::Model& model, const std::vector<float>& values, bool bounds)
{
    const int view = addGltfBufferView(model, values.data(), values.size() * sizeof(float), 0);
    const int accessor = addGltfAccessor(model, view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_SCALAR, values.size());
    if (bounds && !values.empty()) {
        const auto [low, high] = std::minmax_element(values.begin(), values.end());
        model.accessors[std::size_t(accessor)].minValues = {*low};
        model.accessors[std::size_t(accessor)].maxValues = {*high};
    }
    return accessor;
}

// Keyframe f at f/fps; weights are row-major [keyframe][target], target f−1 = 1 at f.
void addAnimation(tinygltf::Model& model, int frameCount, double fps)
{
    const int targets = frameCount - 1;
    std::vector<float> times(static_cast<std::size_t>(frameCount));
    std::vector<float> weights(std::size_t(frameCount) * std::size_t(targets), 0.0f);
    for (int f = 0; f < frameCount; ++f) {
        times[std::size_t(f)] = float(f / fps);
        if (f > 0)
            weights[std::size_t(f) * std::size_t(targets) + std::size_t(f - 1)] = 1.0f;
    }
    tinygltf::AnimationSampler sampler;
    sampler.input = addScalars(model, times, true);
    sampler.output = addScalars(model, weights, false);
    sampler.interpolation = "STEP";
    tinygltf::AnimationChannel channel;
    channel.sampler = 0;
    channel.target_node = 0;
    channel.target_path = "weights";
    tinygltf::Animation animation;
    animation.name = "frames";
    animation.samplers.push_back(sampler);
    animation.channels.push_back(channel);
    model.animations.push_back(animation);
}

void addMorphTargets(tinygltf::Model& model, const Timeline& timeline, tinygltf::Primitive& primitive,
                     tinygltf::Mesh& mesh)
{
    const std::vector<glm::vec3>& base = timeline.base().positions;
    std::vector<glm::vec3> positions = base;
    std::vector<glm::vec3> displacement(base.size());
    for (int f = 1; f < timeline.frameCount(); ++f) {
        const Frame& frame = timeline.frame(f);
        for (std::size_t k = 0; k < frame.vertices.size(); ++k)
            positions[frame.vertices[k]] = frame.after[k];
        for (std::size_t v = 0; v < base.size(); ++v)
            displacement[v] = positions[v] - base[v];
        primitive.targets.push_back({{"POSITION", addDisplacements(model, displacement)}});
        mesh.weights.push_back(0.0);
    }
}

tinygltf::Model buildModel(const Timeline& timeline, double fps)
{
    tinygltf::Model model;
    model.asset.generator = "TrimLab timeline export";
    model.buffers.emplace_back();
    tinygltf::Primitive primitive;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.attributes["POSITION"] = addBasePositions(model, timeline.base().positions);
    primitive.indices = addGltfTriangleIndices(model, timeline.base().triangles);
    tinygltf::Mesh mesh;
    mesh.name = "timeline";
    addMorphTargets(model, timeline, primitive, mesh);
    mesh.primitives.push_back(primitive);
    model.meshes.push_back(mesh);
    tinygltf::Node node;
    node.mesh = 0;
    node.name = "timeline";
    model.nodes.push_back(node);
    tinygltf::Scene scene;
    scene.nodes = {0};
    model.scenes.push_back(scene);
    model.defaultScene = 0;
    if (timeline.frameCount() > 1)
        addAnimation(model, timeline.frameCount(), fps);
    return model;
}

bool hasGlbExtension(const std::filesystem::path& path)
{
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".glb";
}

} // namespace

std::string morphGltf(const Timeline& timeline, double fps, bool binary)
{
    if (!(std::isfinite(fps) && fps > 0.0))
        throw std::invalid_argument("morphGltf: fps must be finite and > 0, not " + std::to_string(fps));
    if (timeline.base().triangles.empty())
        throw std::invalid_argument("morphGltf: the base mesh has no triangles");
    const tinygltf::Model model = buildModel(timeline, fps);
    std::ostringstream out;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, out, !binary, binary))
        throw std::runtime_error("tinygltf could not serialise the timeline animation");
    return out.str();
}

void exportMorphGltf(const Timeline& timeline, const std::filesystem::path& path, double fps)
{
    const std::string bytes = morphGltf(timeline, fps, hasGlbExtension(path));
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    out.close();
    if (!out)
        throw std::runtime_error("cannot write " + path.string() + ": " + std::strerror(errno));
}

} // namespace trimlab::timeline
