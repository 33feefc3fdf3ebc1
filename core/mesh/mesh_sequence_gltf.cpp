#include "core/mesh/mesh_sequence_gltf.h"

#include "core/io/file_extension.h"
#include "core/io/atomic_write.h"
#include "core/io/gltf_builder.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace trimlab {

namespace {

void requireWritable(const SequenceMesh& item)
{
    const TriangleMesh& mesh = item.mesh;
    for (const glm::vec3& p : mesh.positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw std::invalid_argument("mesh '" + item.name + "' has a non-finite position");
    for (const glm::uvec3& t : mesh.triangles)
        if (std::max({t.x, t.y, t.z}) >= mesh.vertexCount())
            throw std::invalid_argument("mesh '" + item.name + "' has a triangle index past its " +
                                        std::to_string(mesh.vertexCount()) + " vertices");
}

int addMesh(tinygltf::Model& model, const SequenceMesh& item)
{
    tinygltf::Primitive primitive;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.attributes["POSITION"] =
        io::addGltfVec3Accessor(model, item.mesh.positions, TINYGLTF_TARGET_ARRAY_BUFFER, true);
    primitive.indices = io::addGltfTriangleIndices(model, item.mesh.triangles);
    tinygltf::Mesh mesh;
    mesh.name = item.name;
    mesh.primitives.push_back(primitive);
    model.meshes.push_back(mesh);
    return int(model.meshes.size() - 1);
}

// The node of `item`; an empty mesh (a pose whose solid is empty) gets a node without a
// mesh, keyed like the others, so that the sequence keeps its timing and shows nothing.
int addMeshNode(tinygltf::Model& model, const SequenceMesh& item, bool visible)
{
    tinygltf::Node node;
    node.name = item.name;
    if (!visible)
        node.scale = {0.0, 0.0, 0.0};
    if (!item.mesh.triangles.empty())
        node.mesh = addMesh(model, item);
    model.nodes.push_back(node);
    return int(model.nodes.size() - 1);
}

// Node `node` (mesh k of n) at scale 1 from time k·dt until (k + 1)·dt, else 0: the
// fewest STEP keys that say it.
void addVisibilityChannel(tinygltf::Model& model, tinygltf::Animation& animation, int node, std::size_t k,
                          std::size_t n, double dt)
{
    std::vector<float> times, scales;
    auto key = [&](std::size_t at, float scale) {
        times.push_back(float(double(at) * dt));
        scales.insert(scales.end(), {scale, scale, scale});
    };
    if (k > 0)
        key(0, 0.0f);
    key(k, 1.0f);
    if (k + 1 < n)
        key(k + 1, 0.0f);
    tinygltf::AnimationSampler sampler;
    sampler.input = io::addGltfFloatAccessor(model, times, TINYGLTF_TYPE_SCALAR, true);
    sampler.output = io::addGltfFloatAccessor(model, scales, TINYGLTF_TYPE_VEC3, false);
    sampler.interpolation = "STEP";
    tinygltf::AnimationChannel channel;
    channel.sampler = int(animation.samplers.size());
    channel.target_node = node;
    channel.target_path = "scale";
    animation.samplers.push_back(sampler);
    animation.channels.push_back(channel);
}

std::string sequenceBytes(std::span<const SequenceMesh> meshes, double dt, std::string_view comment, bool binary)
{
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = comment.empty() ? std::string("TrimLab") : "TrimLab: " + std::string(comment);
    model.buffers.emplace_back();
    tinygltf::Node root;
    root.name = "sequence";
    tinygltf::Animation animation;
    animation.name = "poses";
    for (std::size_t k = 0; k < meshes.size(); ++k) {
        const int node = addMeshNode(model, meshes[k], k == 0);
        root.children.push_back(node);
        if (meshes.size() > 1)
            addVisibilityChannel(model, animation, node, k, meshes.size(), dt);
    }
    model.nodes.push_back(root);
    tinygltf::Scene scene;
    scene.nodes = {int(model.nodes.size() - 1)};
    model.scenes.push_back(scene);
    model.defaultScene = 0;
    if (!animation.channels.empty())
        model.animations.push_back(animation);
    std::ostringstream out;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, out, !binary, binary))
        throw std::runtime_error("tinygltf could not serialise the mesh sequence");
    return out.str();
}

} // namespace

void saveMeshSequenceGltf(const std::filesystem::path& path, std::span<const SequenceMesh> meshes,
                          double secondsPerMesh, std::string_view comment)
{
    const std::string ext = io::lowercaseExtension(path);
    if (ext != ".gltf" && ext != ".glb")
        throw std::invalid_argument(path.string() + ": a mesh sequence is written as glTF (.gltf or .glb)");
    if (meshes.empty())
        throw std::invalid_argument(path.string() + ": no mesh to write");
    if (!(secondsPerMesh > 0.0) || !std::isfinite(secondsPerMesh))
        throw std::invalid_argument(path.string() + ": the time per mesh must be finite and > 0");
    for (const SequenceMesh& item : meshes)
        requireWritable(item);
    if (std::all_of(meshes.begin(), meshes.end(), [](const SequenceMesh& m) { return m.mesh.triangles.empty(); }))
        throw std::invalid_argument(path.string() + ": every mesh is empty, so the sequence would show nothing");
    io::writeFileAtomically(path, sequenceBytes(meshes, secondsPerMesh, comment, ext == ".glb"));
}

} // namespace trimlab
