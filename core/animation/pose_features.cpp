#include "core/animation/pose_features.h"

#include <algorithm>
#include <stdexcept>

namespace trimlab {

namespace {

std::vector<double> differences(const MeshAnimation& animation, std::size_t pose, FeatureKind kind)
{
    const std::vector<glm::vec3>& now = animation.poses[pose];
    const std::vector<glm::vec3>& before = animation.poses[pose - 1];
    std::vector<double> values;
    values.reserve(3 * now.size());
    for (std::size_t v = 0; v < now.size(); ++v) {
        glm::dvec3 d = glm::dvec3(now[v]) - glm::dvec3(before[v]);
        if (kind == FeatureKind::Acceleration)
            d = glm::dvec3(animation.poses[pose + 1][v]) - glm::dvec3(now[v]) - d;
        values.insert(values.end(), {d.x, d.y, d.z});
    }
    return values;
}

} // namespace

std::vector<std::size_t> featurePoses(std::size_t poseCount, std::size_t restPose, const FeatureSettings& settings)
{
    std::vector<std::size_t> poses;
    const bool fromRest = settings.kind == FeatureKind::RotationAngle && settings.reference == ReferenceMode::Rest;
    const std::size_t end =
        settings.kind == FeatureKind::Acceleration ? (poseCount >= 1 ? poseCount - 1 : 0) : poseCount;
    for (std::size_t p = fromRest ? 0 : 1; p < end; ++p) {
        if (!fromRest || p != restPose)
            poses.push_back(p);
    }
    return poses;
}

std::vector<std::size_t> posesAffectedByEdit(std::size_t poseCount, std::size_t restPose, std::size_t edited,
                                             const FeatureSettings& settings)
{
    const std::vector<std::size_t> all = featurePoses(poseCount, restPose, settings);
    const bool fromRest = settings.kind == FeatureKind::RotationAngle && settings.reference == ReferenceMode::Rest;
    if (fromRest && edited == restPose)
        return all;
    std::vector<std::size_t> affected;
    for (const std::size_t p : all) {
        const bool hit = p == edited || (!fromRest && p == edited + 1) ||
                         (settings.kind == FeatureKind::Acceleration && p + 1 == edited);
        if (hit)
            affected.push_back(p);
    }
    return affected;
}

PoseFeature computePoseFeature(const MeshAnimation& animation, std::size_t pose, const FeatureSettings& settings)
{
    const std::vector<std::size_t> valid = featurePoses(animation.poseCount(), animation.restPose, settings);
    if (!std::binary_search(valid.begin(), valid.end(), pose))
        throw std::invalid_argument("computePoseFeature: pose " + std::to_string(pose) + " has no " +
                                    std::string(featureName(settings.kind)) + " feature");
    PoseFeature feature;
    feature.pose = pose;
    if (settings.kind != FeatureKind::RotationAngle) {
        feature.dimension = 3;
        feature.values = differences(animation, pose, settings.kind);
        return feature;
    }
    const std::size_t reference = settings.reference == ReferenceMode::Rest ? animation.restPose : pose - 1;
    const std::vector<glm::vec3>& from = animation.poses[reference];
    const std::vector<double> faceAngles = faceRotationAngles(from, animation.poses[pose], animation.triangles);
    feature.values =
        vertexRotationAngles(faceAngles, animation.triangles, from, animation.vertexCount(), settings.averaging);
    return feature;
}

std::string_view featureName(FeatureKind kind)
{
    switch (kind) {
    case FeatureKind::RotationAngle:
        return "rotation";
    case FeatureKind::Velocity:
        return "velocity";
    case FeatureKind::Acceleration:
        return "acceleration";
    }
    return "?";
}

std::string_view referenceName(ReferenceMode mode)
{
    return mode == ReferenceMode::Rest ? "rest" : "previous";
}

} // namespace trimlab
