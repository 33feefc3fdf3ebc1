#pragma once
/// \file
/// A scene: the objects TrimLab renders together. The winding index of a point is the sum
/// over all objects (the scene is one self-crossing surface); per-object classification
/// arrives with CSG.

#include "core/mesh/triangle_mesh.h"

#include <glm/mat4x4.hpp>

#include <string>
#include <vector>

namespace trimlab {

/// One renderable object. `modelMatrix` maps object space to world space; it must be
/// orientation preserving (det > 0) so that facing and winding keep their meaning.
struct SceneObject {
    std::string name;
    TriangleMesh mesh;
    glm::dmat4 modelMatrix{1.0};
};

struct Scene {
    /// Objects are identified by their index here (the "object id" of fragments and hits).
    std::vector<SceneObject> objects;

    /// The GPU packs object ids into 5 bits of a fragment (see shaders/common/fragment_pack.glsl).
    static constexpr std::size_t maxObjects = 32;

    [[nodiscard]] Bounds worldBounds() const;
    [[nodiscard]] std::size_t triangleCount() const;
    [[nodiscard]] bool empty() const { return triangleCount() == 0; }
};

} // namespace trimlab
