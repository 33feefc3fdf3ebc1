#include "core/skinning/bone_edit.h"

#include "core/skinning/dual_quaternion.h"
#include "core/skinning/skinning_propagation.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/trigonometric.hpp>

#include <stdexcept>

namespace trimlab {

namespace {

glm::dquat editRotation(const BoneEdit& edit)
{
    const glm::dvec3 radians = glm::radians(edit.rotationDegrees);
    return glm::angleAxis(radians.z, glm::dvec3(0, 0, 1)) * glm::angleAxis(radians.y, glm::dvec3(0, 1, 0)) *
           glm::angleAxis(radians.x, glm::dvec3(1, 0, 0));
}

} // namespace

glm::dvec3 boneCentroid(const SkinningWeights& weights, std::span<const glm::dvec3> positions, std::size_t bone)
{
    if (positions.size() != weights.vertices.size())
        throw std::invalid_argument("bone centroid: one position per weighted vertex is required");
    glm::dvec3 sum(0.0);
    double total = 0.0;
    for (std::size_t j = 0; j < positions.size(); ++j) {
        const VertexInfluences& influences = weights.vertices[j];
        for (std::uint32_t i = 0; i < influences.count; ++i) {
            if (influences.bones[i] != bone)
                continue;
            sum += influences.weights[i] * positions[j];
            total += influences.weights[i];
        }
    }
    if (!(total > 0.0))
        throw std::invalid_argument("bone centroid: the bone influences no vertex");
    return sum / total;
}

Affine3 boneEditMotion(const BoneEdit& edit, const glm::dvec3& centre)
{
    const glm::dmat3 rotation = glm::mat3_cast(editRotation(edit));
    return {rotation, centre + edit.translation - rotation * centre};
}

SkinningModel applyBoneEdit(const SkinningModel& model, std::size_t pose, std::size_t bone, const BoneEdit& edit,
                            std::span<const glm::dvec3> posed)
{
    if (pose >= model.poseCount() || bone >= model.boneCount())
        throw std::invalid_argument("bone edit: pose or bone out of range");
    if (pose == model.restPose)
        throw std::invalid_argument("bone edit: the rest pose has no bone transform to edit");
    const glm::dvec3 centre = boneCentroid(model.weights, posed, bone);
    if (model.method == SkinningMethod::Lbs)
        return setBoneTransform(model, pose, bone, compose(boneEditMotion(edit, centre), model.affine[pose][bone]));
    const glm::dquat rotation = editRotation(edit);
    const DualQuaternion motion =
        dualQuaternionFromRigid(rotation, centre + edit.translation - glm::mat3_cast(rotation) * centre);
    return setBoneTransform(model, pose, bone, motion * model.rigid[pose][bone]);
}

} // namespace trimlab
