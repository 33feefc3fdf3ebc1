#pragma once
/// \file
/// A Scene uploaded to the GPU: one vertex/normal/index buffer for all objects, drawn
/// object by object, and the same buffers exposed as shader storage so that resolve
/// passes can shade a stored fragment from its (object id, primitive id) alone.

#include "render/gl/gl_functions.h"
#include "render/gl/gl_objects.h"

#include "core/scene/scene.h"

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <vector>

namespace trimlab::render {

/// Where one object's geometry lives in a GpuScene's buffers, for compute passes that
/// rewrite it in place (frame/gpu_skinning.h): positions and normals are tightly packed
/// float xyz per vertex, the object's vertices starting at `baseVertex`.
struct GpuObjectGeometry {
    GLuint positions = 0;
    GLuint normals = 0;
    std::size_t baseVertex = 0;
    std::size_t vertexCount = 0;
    std::size_t triangleCount = 0;
};

class GpuScene {
public:
    explicit GpuScene(GlFunctions& gl);

    /// Replaces the uploaded scene. Throws GpuMemoryError when the buffers do not fit and
    /// std::invalid_argument when the scene exceeds the fragment format (32 objects,
    /// 2^24 triangles per object).
    void upload(const Scene& scene);

    /// Replaces the positions of object `objectIndex` (same vertex count as uploaded; e.g. the
    /// next pose of an animation) and recomputes its normals. Connectivity is unchanged.
    /// Throws std::invalid_argument on a count mismatch.
    void updatePositions(std::size_t objectIndex, const std::vector<glm::vec3>& positions);

    /// The buffers and range of object `objectIndex`, for a pass that writes its positions
    /// and normals on the GPU instead of updatePositions. Throws std::invalid_argument for an
    /// index beyond the uploaded objects.
    [[nodiscard]] GpuObjectGeometry objectGeometry(std::size_t objectIndex) const;

    /// Object `objectIndex`'s positions or normals as the GPU holds them now, read back
    /// (object space; waits for the passes that wrote them): what a GPU evaluation is
    /// compared with the CPU's by (render.gpu_skinning, render.gpu_subdivision, the
    /// skinning bench). Throws as objectGeometry.
    [[nodiscard]] std::vector<glm::vec3> readPositions(std::size_t objectIndex) const;
    [[nodiscard]] std::vector<glm::vec3> readNormals(std::size_t objectIndex) const;

    /// Replaces the model matrix of object `objectIndex` (e.g. the Scene panel moved it)
    /// without re-uploading any geometry; takes effect with the next setView(). The matrix
    /// must be orientation preserving (SceneObject's rule). Throws std::invalid_argument
    /// for an index beyond the uploaded objects.
    void setModelMatrix(std::size_t objectIndex, const glm::dmat4& model);

    /// Per-vertex colors for the whole scene (RGBA8, one per uploaded vertex in object
    /// order), shown instead of the trim palette; an empty vector switches them off.
    /// Throws std::invalid_argument on a count mismatch.
    void setVertexColors(const std::vector<std::uint32_t>& rgba8);
    [[nodiscard]] bool hasVertexColors() const { return m_hasVertexColors; }

    /// Updates the per-object view-space transforms for `view` (call once per frame).
    void setView(const glm::dmat4& view);

    /// Draws every object with `program`, which must declare `uniform mat4 u_modelView`,
    /// `uniform mat4 u_projection` and `uniform uint u_objectId` (missing ones are skipped).
    void draw(GLuint program, const glm::dmat4& projection);

    /// Binds positions, normals, indices and the object table as shader storage.
    void bindStorage();

    [[nodiscard]] std::size_t objectCount() const { return m_objects.size(); }
    [[nodiscard]] std::size_t triangleCount() const { return m_triangleCount; }
    [[nodiscard]] std::size_t memoryBytes() const { return m_memoryBytes; }

private:
    struct ObjectRange {
        glm::dmat4 model{1.0};
        GLint baseVertex = 0;
        GLsizei indexCount = 0;
        std::size_t indexOffsetBytes = 0;
        std::size_t vertexCount = 0;
        std::vector<glm::uvec3> triangles; // kept for recomputing normals on updatePositions
    };

    GlFunctions& m_gl;
    GlVertexArray m_vao;
    GlBuffer m_positions;
    GlBuffer m_normals;
    GlBuffer m_indices;
    GlBuffer m_objectTable;
    GlBuffer m_colors;
    bool m_hasVertexColors = false;
    std::size_t m_vertexCount = 0;
    std::vector<ObjectRange> m_objects;
    std::vector<glm::dmat4> m_modelView;
    std::size_t m_triangleCount = 0;
    std::size_t m_memoryBytes = 0;
};

} // namespace trimlab::render
