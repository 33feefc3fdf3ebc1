#include "core/animation/gltf_animated_geometry.h"

#include "core/mesh/gltf_accessor.h"
#include "core/mesh/gltf_scene_size.h"
#include "core/mesh/mesh_load_error.h"
#include "core/util/memory_budget.h"

#include <tiny_gltf.h>

#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <numeric>

namespace trimlab {

namespace {

std::vector<glm::dvec3> toVectors(const std::vector<glm::vec3>& values)
{
    return std::vector<glm::dvec3>(values.begin(), values.end());
}

GltfSkin readSkin(const tinygltf::Model& model, std::size_t index, const std::string& name)
{
    const tinygltf::Skin& skin = model.skins[index];
    const GltfReadContext context{name, "skin " + std::to_string(index)};
    GltfSkin result;
    for (const int joint : skin.joints) {
        if (joint < 0 || std::size_t(joint) >= model.nodes.size())
            throw MeshLoadError(name, "joint node " + std::to_string(joint) + " does not exist",
                                {.line = 0, .element = context.element});
        result.joints.push_back(std::size_t(joint));
    }
    result.inverseBind.assign(result.joints.size(), glm::dmat4(1.0));
    if (skin.inverseBindMatrices >= 0) {
        const std::vector<double> m = readGltfNumbers(model, skin.inverseBindMatrices, TINYGLTF_TYPE_MAT4, context);
        if (m.size() != 16 * result.joints.size())
            throw MeshLoadError(name,
                                "has " + std::to_string(result.joints.size()) + " joints but " +
                                    std::to_string(m.size() / 16) + " inverse bind matrices",
                                {.line = 0, .element = context.element});
        for (std::size_t j = 0; j < result.joints.size(); ++j)
            result.inverseBind[j] = glm::make_mat4(m.data() + 16 * j);
    }
    return result;
}

// JOINTS_n / WEIGHTS_n for n = 0, 1, ... while both exist.
void readInfluences(const tinygltf::Model& model, const tinygltf::Primitive& prim, std::size_t jointCount,
                    const GltfReadContext& context, GltfPrimitiveInstance& instance)
{
    const std::size_t count = instance.base.size();
    std::vector<std::vector<double>> joints;
    std::vector<std::vector<double>> weights;
    for (int set = 0;; ++set) {
        const auto j = prim.attributes.find("JOINTS_" + std::to_string(set));
        const auto w = prim.attributes.find("WEIGHTS_" + std::to_string(set));
        if (j == prim.attributes.end() || w == prim.attributes.end())
            break;
        joints.push_back(readGltfNumbers(model, j->second, TINYGLTF_TYPE_VEC4, context));
        weights.push_back(readGltfNumbers(model, w->second, TINYGLTF_TYPE_VEC4, context));
        if (joints.back().size() != 4 * count || weights.back().size() != 4 * count)
            throw MeshLoadError(context.displayName,
                                "JOINTS_" + std::to_string(set) + " or WEIGHTS_" + std::to_string(set) +
                                    " does not have one entry per vertex",
                                {.line = 0, .element = context.element});
    }
    if (joints.empty())
        throw MeshLoadError(context.displayName, "the node has a skin but the primitive has no JOINTS_0 and WEIGHTS_0",
                            {.line = 0, .element = context.element});
    instance.influences = 4 * joints.size();
    for (std::size_t v = 0; v < count; ++v) {
        for (std::size_t s = 0; s < joints.size(); ++s) {
            for (std::size_t c = 0; c < 4; ++c) {
                const double joint = joints[s][4 * v + c];
                if (joint < 0.0 || joint >= double(jointCount) || joint != std::floor(joint))
                    throw MeshLoadError(context.displayName,
                                        "vertex " + std::to_string(v) + " names joint " + std::to_string(joint) +
                                            ", but the skin has " + std::to_string(jointCount) + " joints",
                                        {.line = 0, .element = context.element});
                instance.joints.push_back(std::uint32_t(joint));
                instance.weights.push_back(weights[s][4 * v + c]);
            }
        }
    }
}

std::vector<std::uint32_t> primitiveIndices(const tinygltf::Model& model, const tinygltf::Primitive& prim,
                                            std::size_t vertexCount, const GltfReadContext& context)
{
    std::vector<std::uint32_t> indices(vertexCount);
    if (prim.indices >= 0)
        indices = readGltfIndices(model, prim.indices, vertexCount, context);
    else
        std::iota(indices.begin(), indices.end(), 0u);
    if (indices.size() % 3 != 0)
        throw MeshLoadError(context.displayName,
                            "a TRIANGLES primitive has " + std::to_string(indices.size()) +
                                " indices, which is not a multiple of 3",
                            {.line = 0, .element = context.element});
    return indices;
}

std::vector<std::vector<glm::dvec3>> readTargets(const tinygltf::Model& model, const tinygltf::Primitive& prim,
                                                 std::size_t count, const GltfReadContext& context)
{
    std::vector<std::vector<glm::dvec3>> targets;
    for (const std::map<std::string, int>& target : prim.targets) {
        const auto position = target.find("POSITION");
        targets.emplace_back(count, glm::dvec3(0.0));
        if (position == target.end())
            continue;
        targets.back() = toVectors(readGltfPositions(model, position->second, context));
        if (targets.back().size() != count)
            throw MeshLoadError(context.displayName,
                                "a morph target has " + std::to_string(targets.back().size()) +
                                    " positions but the primitive has " + std::to_string(count),
                                {.line = 0, .element = context.element});
    }
    return targets;
}

} // namespace

namespace {

// Appends the TRIANGLES primitive `p` of the mesh of node `node` to `geometry`.
void addPrimitive(const tinygltf::Model& model, std::size_t node, std::size_t p, bool mirrored, const std::string& name,
                  GltfAnimatedGeometry& geometry)
{
    const tinygltf::Node& n = model.nodes[node];
    const auto meshIndex = std::size_t(n.mesh);
    const tinygltf::Primitive& prim = model.meshes[meshIndex].primitives[p];
    const GltfReadContext context{name, "mesh " + std::to_string(meshIndex) + " primitive " + std::to_string(p)};
    auto fail = [&](const std::string& reason) {
        throw MeshLoadError(name, reason, {.line = 0, .element = context.element});
    };
    const auto position = prim.attributes.find("POSITION");
    if (position == prim.attributes.end())
        fail("the primitive has no POSITION attribute");
    GltfPrimitiveInstance instance;
    instance.node = node;
    instance.skin = n.skin;
    instance.base = toVectors(readGltfPositions(model, position->second, context));
    instance.targets = readTargets(model, prim, instance.base.size(), context);
    if (!geometry.primitives.empty() && geometry.primitives.back().node == node &&
        geometry.primitives.back().targets.size() != instance.targets.size())
        fail("its morph target count differs from the mesh's first primitive");
    if (n.skin >= 0)
        readInfluences(model, prim, geometry.skins[std::size_t(n.skin)].joints.size(), context, instance);
    const std::vector<std::uint32_t> indices = primitiveIndices(model, prim, instance.base.size(), context);
    const auto offset = static_cast<std::uint32_t>(geometry.vertexCount);
    for (std::size_t i = 0; i + 2 < indices.size(); i += 3) {
        const glm::uvec3 t(indices[i], indices[i + 1], indices[i + 2]);
        geometry.triangles.push_back((mirrored ? glm::uvec3(t.x, t.z, t.y) : t) + offset);
    }
    geometry.vertexCount += instance.base.size();
    geometry.primitives.push_back(std::move(instance));
}

void addMeshNode(const tinygltf::Model& model, std::size_t node, const glm::dmat4& fileWorld, const std::string& name,
                 GltfAnimatedGeometry& geometry)
{
    const tinygltf::Node& n = model.nodes[node];
    if (std::size_t(n.mesh) >= model.meshes.size())
        throw MeshLoadError(name, "the node references mesh " + std::to_string(n.mesh) + ", which does not exist",
                            {.line = 0, .element = "node " + std::to_string(node)});
    if (n.skin >= 0 && std::size_t(n.skin) >= model.skins.size())
        throw MeshLoadError(name, "the node references skin " + std::to_string(n.skin) + ", which does not exist",
                            {.line = 0, .element = "node " + std::to_string(node)});
    const bool mirrored = n.skin < 0 && glm::determinant(fileWorld) < 0.0;
    const std::vector<tinygltf::Primitive>& primitives = model.meshes[std::size_t(n.mesh)].primitives;
    for (std::size_t p = 0; p < primitives.size(); ++p) {
        const int mode = primitives[p].mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitives[p].mode;
        if (mode <= TINYGLTF_MODE_LINE_STRIP)
            continue; // points and lines carry no surface
        if (mode != TINYGLTF_MODE_TRIANGLES)
            throw MeshLoadError(
                name,
                "triangle strips and fans are not supported in animations; re-export the mesh as "
                "TRIANGLES",
                {.line = 0, .element = "mesh " + std::to_string(n.mesh) + " primitive " + std::to_string(p)});
        addPrimitive(model, node, p, mirrored, name, geometry);
    }
}

// Σ wᵢ·(world(jointᵢ)·inverseBindᵢ) for one vertex; false when the weights sum to 0.
bool blendMatrix(const GltfPrimitiveInstance& prim, std::size_t v, const std::vector<glm::dmat4>& jointMatrices,
                 glm::dmat4& blended)
{
    double total = 0.0;
    blended = glm::dmat4(0.0);
    for (std::size_t i = 0; i < prim.influences; ++i) {
        const double w = prim.weights[v * prim.influences + i];
        if (w == 0.0)
            continue;
        blended += w * jointMatrices[prim.joints[v * prim.influences + i]];
        total += w;
    }
    if (!(total > 0.0))
        return false;
    blended *= 1.0 / total;
    return true;
}

} // namespace

std::vector<glm::dmat4> jointMatrices(const GltfSkin& skin, const std::vector<glm::dmat4>& world)
{
    std::vector<glm::dmat4> matrices;
    matrices.reserve(skin.joints.size());
    for (std::size_t j = 0; j < skin.joints.size(); ++j)
        matrices.push_back(world[skin.joints[j]] * skin.inverseBind[j]);
    return matrices;
}

std::vector<glm::dvec3> GltfAnimatedGeometry::pose(const std::vector<NodeTransform>& nodes,
                                                   const std::vector<glm::dmat4>& world) const
{
    std::vector<std::vector<glm::dmat4>> skinMatrices;
    for (const GltfSkin& skin : skins)
        skinMatrices.push_back(jointMatrices(skin, world));
    std::vector<glm::dvec3> positions;
    positions.reserve(vertexCount);
    for (const GltfPrimitiveInstance& prim : primitives) {
        const std::vector<double>& weights = nodes[prim.node].weights;
        for (std::size_t v = 0; v < prim.base.size(); ++v) {
            glm::dvec3 p = prim.base[v];
            for (std::size_t t = 0; t < prim.targets.size() && t < weights.size(); ++t)
                p += weights[t] * prim.targets[t][v];
            glm::dmat4 m = world[prim.node];
            if (prim.skin >= 0 && !blendMatrix(prim, v, skinMatrices[std::size_t(prim.skin)], m))
                m = world[prim.node];
            positions.emplace_back(m * glm::dvec4(p, 1.0));
        }
    }
    return positions;
}

namespace {

// Refuses, before any primitive is read, a scene whose mesh instances need more than the
// memory budget (gltf_scene_size.h): rest positions and morph displacements in double
// precision, four joints and weights per vertex, the triangles.
void requireGeometryMemory(const tinygltf::Model& model, const std::vector<std::size_t>& nodes, const std::string& name)
{
    const GltfSceneSize size = gltfSceneSize(model, nodes);
    const std::uint64_t bytes = (size.vertices + size.targetVertices) * sizeof(glm::dvec3) +
                                size.vertices * (4 * sizeof(std::uint32_t) + 4 * sizeof(double)) +
                                size.indices * sizeof(std::uint32_t);
    try {
        requireMemory(bytes,
                      "the scene's " + std::to_string(size.instances) + " mesh instances (" +
                          std::to_string(size.vertices) + " vertices, " + std::to_string(size.targetVertices) +
                          " morph-target vertices)",
                      "reference fewer meshes from the file's nodes");
    } catch (const MemoryBudgetError& e) {
        throw MeshLoadError(name, e.what());
    }
}

} // namespace

GltfAnimatedGeometry readAnimatedGeometry(const tinygltf::Model& model, const std::vector<int>& parents,
                                          const std::string& name)
{
    GltfAnimatedGeometry geometry;
    for (std::size_t s = 0; s < model.skins.size(); ++s)
        geometry.skins.push_back(readSkin(model, s, name));
    const std::vector<glm::dmat4> fileWorld = worldMatrices(fileNodeTransforms(model, name), parents);
    const std::vector<std::size_t> nodes = gltfSceneNodes(model, gltfSceneRoots(model, name), name);
    requireGeometryMemory(model, nodes, name);
    for (const std::size_t node : nodes) {
        if (model.nodes[node].mesh >= 0)
            addMeshNode(model, node, fileWorld[node], name, geometry);
    }
    if (geometry.triangles.empty())
        throw MeshLoadError(name, "the scene contains no triangles to animate");
    return geometry;
}

} // namespace trimlab
