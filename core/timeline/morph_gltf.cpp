// exportMorphGltf / morphGltf (declared in frame_export.h): the timeline as a glTF 2.0
// morph-target animation.
#include "core/timeline/frame_export.h"

#include "core/io/gltf_builder.h"
#include "core/io/atomic_write.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <span>
#include <sstream>
#include <stdexcept>

namespace trimlab::timeline {

namespace {

int addBasePositions(tinygltf::Model& model, const std::vector<glm::vec3>& positions)
{
    return io::addGltfVec3Accessor(model, positions, TINYGLTF_TARGET_ARRAY_BUFFER, true);
}

// Keyframe f at f/fps shows frame f: the base, then morph target f−1 alone.
void addAnimation(tinygltf::Model& model, int frameCount, double fps)
{
    std::vector<float> times(static_cast<std::size_t>(frameCount));
    for (int f = 0; f < frameCount; ++f)
        times[std::size_t(f)] = float(f / fps);
    io::addGltfMorphStepAnimation(model, "frames", times, 1);
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
        primitive.targets.push_back({{"POSITION", io::addGltfSparseVec3Accessor(model, displacement)}});
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
    primitive.indices = io::addGltfTriangleIndices(model, timeline.base().triangles);
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
    io::writeFileAtomically(path, morphGltf(timeline, fps, hasGlbExtension(path)));
}

} // namespace trimlab::timeline
