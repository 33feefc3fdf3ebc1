#include "core/mesh/gltf_reader.h"

#include "core/mesh/gltf_accessor.h"
#include "core/mesh/gltf_document.h"
#include "core/mesh/gltf_scene_size.h"
#include "core/mesh/mesh_load_error.h"
#include "core/mesh/reader_support.h"
#include "core/mesh/vertex_welding.h"
#include "core/util/memory_budget.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <numeric>

namespace trimlab {

namespace {

void requireSize(const std::vector<double>& values, std::size_t size, const char* what, int node,
                 const std::string& name)
{
    if (!values.empty() && values.size() != size)
        throw MeshLoadError(name,
                            std::string("'") + what + "' must have " + std::to_string(size) + " numbers, not " +
                                std::to_string(values.size()),
                            {.line = 0, .element = "node " + std::to_string(node)});
}

glm::dmat4 localMatrix(const tinygltf::Node& node, int index, const std::string& name)
{
    requireSize(node.matrix, 16, "matrix", index, name);
    requireSize(node.translation, 3, "translation", index, name);
    requireSize(node.rotation, 4, "rotation", index, name);
    requireSize(node.scale, 3, "scale", index, name);
    if (!node.matrix.empty())
        return glm::make_mat4(node.matrix.data()); // column-major, as glTF stores it
    glm::dmat4 m(1.0);
    if (!node.translation.empty())
        m = glm::translate(m, glm::make_vec3(node.translation.data()));
    if (!node.rotation.empty()) {
        const auto& r = node.rotation;
        const glm::dquat q(r[3], r[0], r[1], r[2]); // glTF stores x, y, z, w
        if (!(glm::length(q) > 0.0))
            throw MeshLoadError(name, "the rotation quaternion is zero",
                                {.line = 0, .element = "node " + std::to_string(index)});
        m *= glm::mat4_cast(glm::normalize(q));
    }
    if (!node.scale.empty())
        m = glm::scale(m, glm::make_vec3(node.scale.data()));
    return m;
}

// Vertex indices of a primitive in the order its mode lists them, as triangles.
std::vector<glm::uvec3> assembleTriangles(int mode, const std::vector<std::uint32_t>& v, const GltfReadContext& context)
{
    std::vector<glm::uvec3> triangles;
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        if (v.size() % 3 != 0)
            throw MeshLoadError(context.displayName,
                                "a TRIANGLES primitive has " + std::to_string(v.size()) +
                                    " indices, which is not a multiple of 3",
                                {.line = 0, .element = context.element});
        triangles.reserve(v.size() / 3);
        for (std::size_t i = 0; i + 2 < v.size(); i += 3)
            triangles.emplace_back(v[i], v[i + 1], v[i + 2]);
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (std::size_t i = 0; i + 2 < v.size(); ++i) // every other triangle flipped to keep winding
            triangles.emplace_back(v[i], v[i + 1 + i % 2], v[i + 2 - i % 2]);
    } else {
        for (std::size_t i = 1; i + 1 < v.size(); ++i)
            triangles.emplace_back(v[i], v[i + 1], v[0]);
    }
    return triangles;
}

// Accumulates the triangles of the traversed nodes.
class SceneCollector {
public:
    SceneCollector(const tinygltf::Model& model, const std::string& name) : m_model(model), m_name(name) {}

    void addNode(int index, const glm::dmat4& world);
    TriangleMesh take();

private:
    void addPrimitive(std::size_t mesh, std::size_t primitive, const glm::dmat4& world);

    const tinygltf::Model& m_model;
    const std::string& m_name;
    TriangleMesh m_mesh;
    std::size_t m_skippedPrimitives = 0; // points and lines
};

void SceneCollector::addNode(int index, const glm::dmat4& world)
{
    const int meshIndex = m_model.nodes[static_cast<std::size_t>(index)].mesh;
    if (meshIndex < 0)
        return;
    if (static_cast<std::size_t>(meshIndex) >= m_model.meshes.size())
        throw MeshLoadError(m_name,
                            "the node references mesh " + std::to_string(meshIndex) + ", but the file has " +
                                countNoun(m_model.meshes.size(), "mesh", "meshes"),
                            {.line = 0, .element = "node " + std::to_string(index)});
    const auto mesh = static_cast<std::size_t>(meshIndex);
    for (std::size_t p = 0; p < m_model.meshes[mesh].primitives.size(); ++p)
        addPrimitive(mesh, p, world);
}

void SceneCollector::addPrimitive(std::size_t mesh, std::size_t primitive, const glm::dmat4& world)
{
    const tinygltf::Primitive& prim = m_model.meshes[mesh].primitives[primitive];
    const GltfReadContext context{m_name, "mesh " + std::to_string(mesh) + " primitive " + std::to_string(primitive)};
    const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
    if (mode <= TINYGLTF_MODE_LINE_STRIP) {
        ++m_skippedPrimitives;
        return;
    }
    auto fail = [&](const std::string& reason) {
        throw MeshLoadError(m_name, reason, {.line = 0, .element = context.element});
    };
    if (mode > TINYGLTF_MODE_TRIANGLE_FAN)
        fail("unknown primitive mode " + std::to_string(mode));
    if (prim.extensions.count("KHR_draco_mesh_compression"))
        fail("Draco-compressed primitives are not supported; re-export without mesh compression");
    const auto position = prim.attributes.find("POSITION");
    if (position == prim.attributes.end())
        fail("the primitive has no POSITION attribute");
    const std::vector<glm::vec3> local = readGltfPositions(m_model, position->second, context);
    std::vector<std::uint32_t> indices(local.size());
    if (prim.indices >= 0)
        indices = readGltfIndices(m_model, prim.indices, local.size(), context);
    else
        std::iota(indices.begin(), indices.end(), 0u);
    const std::vector<glm::uvec3> triangles = assembleTriangles(mode, indices, context);
    if (m_mesh.positions.size() + local.size() > kMaxMeshVertices)
        fail("the scene has more than 4294967295 vertices");
    const auto offset = static_cast<std::uint32_t>(m_mesh.positions.size());
    for (const glm::vec3& p : local) {
        const glm::dvec3 q(world * glm::dvec4(glm::dvec3(p), 1.0));
        if (!isFiniteFloat(q.x) || !isFiniteFloat(q.y) || !isFiniteFloat(q.z))
            fail("a vertex is not finite after applying the node transform");
        m_mesh.positions.emplace_back(q);
    }
    const bool mirrored = glm::determinant(world) < 0.0;
    for (const glm::uvec3& t : triangles)
        m_mesh.triangles.push_back(mirrored ? glm::uvec3(t[0], t[2], t[1]) + offset : t + offset);
}

TriangleMesh SceneCollector::take()
{
    if (m_mesh.triangles.empty())
        throw MeshLoadError(m_name, m_skippedPrimitives > 0
                                        ? "the scene contains no triangles, only points or lines"
                                        : "the scene contains no triangles (no node with a triangle mesh)");
    return std::move(m_mesh);
}

// Refuses, before anything is read, a scene that needs more than the memory budget
// (gltf_scene_size.h): the positions in the scene and in the welding table, the indices
// and one remapped index per vertex.
void requireSceneMemory(const tinygltf::Model& model, const std::vector<int>& roots, const std::string& name)
{
    const GltfSceneSize size = gltfSceneSize(model, gltfSceneNodes(model, roots, name));
    const std::uint64_t bytes =
        size.vertices * (sizeof(glm::vec3) * 2 + sizeof(std::uint32_t) * 2) + size.indices * sizeof(std::uint32_t) * 2;
    try {
        requireMemory(bytes,
                      "the scene's " + std::to_string(size.instances) + " mesh instances (" +
                          std::to_string(size.vertices) + " vertices)",
                      "reference fewer meshes from the file's nodes");
    } catch (const MemoryBudgetError& e) {
        throw MeshLoadError(name, e.what());
    }
}

TriangleMesh collectScene(const tinygltf::Model& model, const std::string& name)
{
    struct Pending {
        int node;
        glm::dmat4 parentWorld;
    };
    std::vector<Pending> stack;
    const std::vector<int> roots = gltfSceneRoots(model, name);
    // Its walk (gltfSceneNodes) has checked that every node exists and that they form
    // trees; this one composes the transforms, holding only the pending children.
    requireSceneMemory(model, roots, name);
    for (auto it = roots.rbegin(); it != roots.rend(); ++it)
        stack.push_back({*it, glm::dmat4(1.0)});
    SceneCollector collector(model, name);
    while (!stack.empty()) {
        const Pending next = stack.back();
        stack.pop_back();
        const auto index = static_cast<std::size_t>(next.node);
        const glm::dmat4 world = next.parentWorld * localMatrix(model.nodes[index], next.node, name);
        collector.addNode(next.node, world);
        const std::vector<int>& children = model.nodes[index].children;
        for (auto it = children.rbegin(); it != children.rend(); ++it)
            stack.push_back({*it, world});
    }
    return collector.take();
}

} // namespace

TriangleMesh readGltf(std::string_view bytes, const std::string& displayName, const std::filesystem::path& baseDir)
{
    // glTF exporters split vertices wherever a normal or texture coordinate changes (and
    // primitives never share vertices), which would leave a closed model full of
    // boundary edges. Positions are all TrimLab renders, so bit-identical ones are joined
    // back: the surface's topology is restored and the trim modes work on such files.
    return weldIdenticalVertices(collectScene(parseGltfDocument(bytes, displayName, baseDir), displayName));
}

} // namespace trimlab
