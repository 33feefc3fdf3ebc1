#pragma once
/// \file
/// The geometry one frame of a dynamic rule rasterises (thesis 8.1.2, "Clipping and
/// Trimming with Dynamic Rules"): the reference frame and the current frame together,
/// every triangle coded by its frame class. A triangle whose three vertices did not move
/// is drawn once (class "both"); a moved triangle is drawn twice, at its reference
/// position (class "reference only") and at its current position (class "current only").
/// The class travels as the object id, so every stored-fragment method carries it
/// without a change to its fragment format:
///   object 0: both (frame.class 2), object 1: current only (1), object 2: reference only (0).

#include "core/mesh/triangle_mesh.h"
#include "core/scene/scene.h"
#include "core/trim/trim_image.h"

#include <glm/mat4x4.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace trimlab {

enum class FrameClass : int {
    ReferenceOnly = 0,
    CurrentOnly = 1,
    Both = 2,
};

inline constexpr int kDynamicObjectBoth = 0;
inline constexpr int kDynamicObjectCurrentOnly = 1;
inline constexpr int kDynamicObjectReferenceOnly = 2;

/// Frame class of a fragment of object `objectId` of a DynamicFrameScene.
[[nodiscard]] inline FrameClass frameClassOfObject(int objectId)
{
    return objectId == kDynamicObjectBoth          ? FrameClass::Both
           : objectId == kDynamicObjectCurrentOnly ? FrameClass::CurrentOnly
                                                   : FrameClass::ReferenceOnly;
}
[[nodiscard]] inline bool inReference(FrameClass c)
{
    return c != FrameClass::CurrentOnly;
}
[[nodiscard]] inline bool inCurrent(FrameClass c)
{
    return c != FrameClass::ReferenceOnly;
}

struct DynamicFrameScene {
    Scene scene; ///< exactly three objects, in the order above (some may be empty)
    /// For each object, the index in the original mesh of each of its triangles.
    std::array<std::vector<std::uint32_t>, 3> meshTriangle;
    std::size_t movedTriangles = 0;
};

/// Builds the scene of `reference` and `current` positions of the same connectivity
/// `triangles`. A triangle is unchanged iff its three vertices are bit-identical in both.
/// Throws std::invalid_argument when the position counts differ.
[[nodiscard]] DynamicFrameScene makeDynamicFrameScene(const std::vector<glm::uvec3>& triangles,
                                                      const std::vector<glm::vec3>& reference,
                                                      const std::vector<glm::vec3>& current,
                                                      const glm::dmat4& modelMatrix = glm::dmat4(1.0));

/// `image` (ids of a DynamicFrameScene's objects, as its renderers give them) with the
/// ids of the original mesh: object 0, primitive = the mesh triangle. For exports and
/// picking, so that dynamic and static renders of one mesh read the same.
[[nodiscard]] TrimImage withMeshIds(TrimImage image, const DynamicFrameScene& frame);

} // namespace trimlab
