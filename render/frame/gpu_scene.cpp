#include "render/frame/gpu_scene.h"

#include "render/gl/bindings.h"
#include "render/gl/wide_vector_state.h"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <stdexcept>
#include <string>

namespace trimlab::render {

namespace {

constexpr std::size_t kMaxTrianglesPerObject = std::size_t(1) << 24; // fragment_pack.glsl

// std430 layout of one entry of the object table (shaders/common/scene_data.glsl).
struct GpuObjectEntry {
    float modelView[16];
    float normalMatrix[16]; // mat3 in the upper-left of a mat4 (std430 would pad a mat3 anyway)
    std::uint32_t baseVertex;
    std::uint32_t baseIndex;
    std::uint32_t padding[2];
};
static_assert(sizeof(GpuObjectEntry) == 144);

void validateSceneLimits(const Scene& scene)
{
    if (scene.objects.size() > Scene::maxObjects)
        throw std::invalid_argument("The scene has " + std::to_string(scene.objects.size()) +
                                    " objects; the renderer supports at most " + std::to_string(Scene::maxObjects) +
                                    ".");
    for (const SceneObject& object : scene.objects) {
        if (object.mesh.triangleCount() > kMaxTrianglesPerObject)
            throw std::invalid_argument("Object '" + object.name + "' has " +
                                        std::to_string(object.mesh.triangleCount()) +
                                        " triangles; the renderer supports at most 16,777,216 per object. "
                                        "Split or decimate the mesh.");
    }
}

void uploadBuffer(GlFunctions& gl, GLuint buffer, GLenum target, const void* data, std::size_t bytes, const char* what)
{
    gl.glBindBuffer(target, buffer);
    gl.glBufferData(target, GLsizeiptr(bytes), data, GL_STATIC_DRAW);
    checkAllocation(gl, what, double(bytes));
}

} // namespace

GpuScene::GpuScene(GlFunctions& gl)
    : m_gl(gl), m_vao(gl), m_positions(gl), m_normals(gl), m_indices(gl), m_objectTable(gl), m_colors(gl)
{
}

void GpuScene::upload(const Scene& scene)
{
    const WideVectorStateScope wideVectorState; // the driver may leave it in use (wide_vector_state.h)
    validateSceneLimits(scene);
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::uvec3> triangles;
    m_objects.clear();
    for (const SceneObject& object : scene.objects) {
        ObjectRange range;
        range.model = object.modelMatrix;
        range.baseVertex = GLint(positions.size());
        range.indexCount = GLsizei(object.mesh.triangleCount() * 3);
        range.indexOffsetBytes = triangles.size() * sizeof(glm::uvec3);
        range.vertexCount = object.mesh.vertexCount();
        range.triangles = object.mesh.triangles;
        const std::vector<glm::vec3> objectNormals = vertexNormals(object.mesh);
        positions.insert(positions.end(), object.mesh.positions.begin(), object.mesh.positions.end());
        normals.insert(normals.end(), objectNormals.begin(), objectNormals.end());
        triangles.insert(triangles.end(), object.mesh.triangles.begin(), object.mesh.triangles.end());
        m_objects.push_back(range);
    }
    m_triangleCount = triangles.size();

    m_gl.glBindVertexArray(m_vao.id());
    uploadBuffer(m_gl, m_positions.id(), GL_ARRAY_BUFFER, positions.data(), positions.size() * sizeof(glm::vec3),
                 "vertex positions");
    m_gl.glEnableVertexAttribArray(0);
    m_gl.glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    uploadBuffer(m_gl, m_normals.id(), GL_ARRAY_BUFFER, normals.data(), normals.size() * sizeof(glm::vec3),
                 "vertex normals");
    m_gl.glEnableVertexAttribArray(1);
    m_gl.glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    uploadBuffer(m_gl, m_indices.id(), GL_ELEMENT_ARRAY_BUFFER, triangles.data(), triangles.size() * sizeof(glm::uvec3),
                 "triangle indices");
    m_gl.glBindVertexArray(0);
    uploadBuffer(m_gl, m_objectTable.id(), GL_SHADER_STORAGE_BUFFER, nullptr,
                 std::max<std::size_t>(1, m_objects.size()) * sizeof(GpuObjectEntry), "object table");
    m_memoryBytes = (positions.size() + normals.size()) * sizeof(glm::vec3) + triangles.size() * sizeof(glm::uvec3) +
                    m_objects.size() * sizeof(GpuObjectEntry);
    m_vertexCount = positions.size();
    setVertexColors({});
    setView(glm::dmat4(1.0));
}

void GpuScene::updatePositions(std::size_t objectIndex, const std::vector<glm::vec3>& positions)
{
    const WideVectorStateScope wideVectorState; // the driver may leave it in use (wide_vector_state.h)
    if (objectIndex >= m_objects.size() || positions.size() != m_objects[objectIndex].vertexCount)
        throw std::invalid_argument(
            "updatePositions: object " + std::to_string(objectIndex) + " has " +
            std::to_string(objectIndex < m_objects.size() ? m_objects[objectIndex].vertexCount : 0) +
            " vertices, got " + std::to_string(positions.size()) + ".");
    const ObjectRange& object = m_objects[objectIndex];
    const std::vector<glm::vec3> normals = vertexNormals(TriangleMesh{positions, object.triangles});
    const auto offset = GLintptr(std::size_t(object.baseVertex) * sizeof(glm::vec3));
    const auto bytes = GLsizeiptr(positions.size() * sizeof(glm::vec3));
    m_gl.glBindBuffer(GL_ARRAY_BUFFER, m_positions.id());
    m_gl.glBufferSubData(GL_ARRAY_BUFFER, offset, bytes, positions.data());
    m_gl.glBindBuffer(GL_ARRAY_BUFFER, m_normals.id());
    m_gl.glBufferSubData(GL_ARRAY_BUFFER, offset, bytes, normals.data());
}

GpuObjectGeometry GpuScene::objectGeometry(std::size_t objectIndex) const
{
    if (objectIndex >= m_objects.size())
        throw std::invalid_argument("objectGeometry: object " + std::to_string(objectIndex) + " does not exist; " +
                                    "the scene has " + std::to_string(m_objects.size()) + " objects.");
    const ObjectRange& object = m_objects[objectIndex];
    return {m_positions.id(), m_normals.id(), std::size_t(object.baseVertex), object.vertexCount,
            object.triangles.size()};
}

namespace {

std::vector<glm::vec3> readVec3s(GlFunctions& gl, GLuint buffer, std::size_t first, std::size_t count)
{
    std::vector<glm::vec3> values(count);
    gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
    gl.glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, GLintptr(first * sizeof(glm::vec3)),
                          GLsizeiptr(count * sizeof(glm::vec3)), values.data());
    return values;
}

} // namespace

std::vector<glm::vec3> GpuScene::readPositions(std::size_t objectIndex) const
{
    const WideVectorStateScope wideVectorState; // the driver may leave it in use (wide_vector_state.h)
    const GpuObjectGeometry object = objectGeometry(objectIndex);
    return readVec3s(m_gl, object.positions, object.baseVertex, object.vertexCount);
}

std::vector<glm::vec3> GpuScene::readNormals(std::size_t objectIndex) const
{
    const WideVectorStateScope wideVectorState; // the driver may leave it in use (wide_vector_state.h)
    const GpuObjectGeometry object = objectGeometry(objectIndex);
    return readVec3s(m_gl, object.normals, object.baseVertex, object.vertexCount);
}

void GpuScene::setModelMatrix(std::size_t objectIndex, const glm::dmat4& model)
{
    if (objectIndex >= m_objects.size())
        throw std::invalid_argument("setModelMatrix: object " + std::to_string(objectIndex) + " does not exist; " +
                                    "the scene has " + std::to_string(m_objects.size()) + " objects.");
    m_objects[objectIndex].model = model;
}

void GpuScene::setVertexColors(const std::vector<std::uint32_t>& rgba8)
{
    if (!rgba8.empty() && rgba8.size() != m_vertexCount)
        throw std::invalid_argument("setVertexColors: the scene has " + std::to_string(m_vertexCount) +
                                    " vertices, got " + std::to_string(rgba8.size()) + " colors.");
    m_hasVertexColors = !rgba8.empty();
    // Never an empty buffer: the resolve shaders always declare the block.
    const std::uint32_t white = 0xFFFFFFFFu;
    const void* data = m_hasVertexColors ? static_cast<const void*>(rgba8.data()) : &white;
    uploadBuffer(m_gl, m_colors.id(), GL_SHADER_STORAGE_BUFFER, data,
                 m_hasVertexColors ? rgba8.size() * sizeof(std::uint32_t) : sizeof(white), "vertex colors");
}

void GpuScene::setView(const glm::dmat4& view)
{
    std::vector<GpuObjectEntry> entries(m_objects.size());
    m_modelView.resize(m_objects.size());
    for (std::size_t i = 0; i < m_objects.size(); ++i) {
        m_modelView[i] = view * m_objects[i].model;
        const glm::mat4 modelView(m_modelView[i]);
        const glm::mat4 normalMatrix(glm::dmat4(glm::inverseTranspose(glm::dmat3(m_modelView[i]))));
        std::copy_n(glm::value_ptr(modelView), 16, entries[i].modelView);
        std::copy_n(glm::value_ptr(normalMatrix), 16, entries[i].normalMatrix);
        entries[i].baseVertex = std::uint32_t(m_objects[i].baseVertex);
        entries[i].baseIndex = std::uint32_t(m_objects[i].indexOffsetBytes / sizeof(std::uint32_t));
    }
    if (entries.empty())
        return;
    m_gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, m_objectTable.id());
    m_gl.glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(entries.size() * sizeof(GpuObjectEntry)),
                         entries.data());
}

void GpuScene::draw(GLuint program, const glm::dmat4& projection)
{
    m_gl.glUseProgram(program);
    const GLint modelViewLocation = m_gl.glGetUniformLocation(program, "u_modelView");
    const GLint projectionLocation = m_gl.glGetUniformLocation(program, "u_projection");
    const GLint objectLocation = m_gl.glGetUniformLocation(program, "u_objectId");
    const glm::mat4 projectionF(projection);
    m_gl.glUniformMatrix4fv(projectionLocation, 1, GL_FALSE, glm::value_ptr(projectionF));
    m_gl.glBindVertexArray(m_vao.id());
    for (std::size_t i = 0; i < m_objects.size(); ++i) {
        const ObjectRange& object = m_objects[i];
        if (object.indexCount == 0)
            continue;
        const glm::mat4 modelView(m_modelView[i]);
        m_gl.glUniformMatrix4fv(modelViewLocation, 1, GL_FALSE, glm::value_ptr(modelView));
        m_gl.glUniform1ui(objectLocation, GLuint(i));
        m_gl.glDrawElementsBaseVertex(GL_TRIANGLES, object.indexCount, GL_UNSIGNED_INT,
                                      reinterpret_cast<const void*>(object.indexOffsetBytes), object.baseVertex);
    }
    m_gl.glBindVertexArray(0);
}

void GpuScene::bindStorage()
{
    m_gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kSceneColorsStorage, m_colors.id());
    m_gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kScenePositionsStorage, m_positions.id());
    m_gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kSceneNormalsStorage, m_normals.id());
    m_gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kSceneIndicesStorage, m_indices.id());
    m_gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kSceneObjectsStorage, m_objectTable.id());
}

} // namespace trimlab::render
