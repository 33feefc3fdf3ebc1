#include "core/trim/dynamic_frame_scene.h"

#include <cstring>
#include <stdexcept>

namespace trimlab {

namespace {

// Bit identity, not ==: a vertex written with the same value is unchanged, and -0.0
// versus 0.0 counts as a move (it is one as far as the stored bits go).
bool sameBits(const glm::vec3& a, const glm::vec3& b)
{
    return std::memcmp(&a, &b, sizeof(glm::vec3)) == 0;
}

bool triangleMoved(const glm::uvec3& t, const std::vector<glm::vec3>& reference, const std::vector<glm::vec3>& current)
{
    for (int corner = 0; corner < 3; ++corner) {
        if (!sameBits(reference[t[corner]], current[t[corner]]))
            return true;
    }
    return false;
}

SceneObject namedObject(const char* name, const std::vector<glm::vec3>& positions, const glm::dmat4& model)
{
    SceneObject object;
    object.name = name;
    object.mesh.positions = positions;
    object.modelMatrix = model;
    return object;
}

} // namespace

DynamicFrameScene makeDynamicFrameScene(const std::vector<glm::uvec3>& triangles,
                                        const std::vector<glm::vec3>& reference, const std::vector<glm::vec3>& current,
                                        const glm::dmat4& modelMatrix)
{
    if (reference.size() != current.size())
        throw std::invalid_argument("the reference frame has " + std::to_string(reference.size()) +
                                    " vertices but the current frame has " + std::to_string(current.size()) + ".");
    DynamicFrameScene result;
    // Unchanged and current-only triangles index the current positions, reference-only
    // ones the reference positions; each object keeps a full vertex array so that
    // triangle indices stay the mesh's own.
    result.scene.objects.push_back(namedObject("both frames", current, modelMatrix));
    result.scene.objects.push_back(namedObject("current frame only", current, modelMatrix));
    result.scene.objects.push_back(namedObject("reference frame only", reference, modelMatrix));
    for (std::uint32_t index = 0; index < triangles.size(); ++index) {
        const glm::uvec3& t = triangles[index];
        if (!triangleMoved(t, reference, current)) {
            result.scene.objects[kDynamicObjectBoth].mesh.triangles.push_back(t);
            result.meshTriangle[kDynamicObjectBoth].push_back(index);
            continue;
        }
        ++result.movedTriangles;
        result.scene.objects[kDynamicObjectCurrentOnly].mesh.triangles.push_back(t);
        result.meshTriangle[kDynamicObjectCurrentOnly].push_back(index);
        result.scene.objects[kDynamicObjectReferenceOnly].mesh.triangles.push_back(t);
        result.meshTriangle[kDynamicObjectReferenceOnly].push_back(index);
    }
    return result;
}

TrimImage withMeshIds(TrimImage image, const DynamicFrameScene& frame)
{
    for (TrimPixel& pixel : image.pixels) {
        if (!pixel.covered() || pixel.objectId < 0 || pixel.objectId > 2)
            continue;
        const std::vector<std::uint32_t>& map = frame.meshTriangle[std::size_t(pixel.objectId)];
        if (std::size_t(pixel.primitiveId) < map.size())
            pixel.primitiveId = std::int32_t(map[std::size_t(pixel.primitiveId)]);
        pixel.objectId = 0;
    }
    return image;
}

} // namespace trimlab
