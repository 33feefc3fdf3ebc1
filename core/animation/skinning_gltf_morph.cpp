// The morph-target half of skinnedGltf (skinning_gltf.h): one target per pose and a STEP
// "weights" channel on the mesh node selecting it.
#include "animation/skinning_gltf_parts.h"

namespace trimlab::skinning_gltf {

namespace {

// Target t: pose t minus the written base, rounded to float; `exported` receives
// base + displacement as a loader adds them.
void addTargets(tinygltf::Model& model, const std::vector<PosePositions>& poses, const std::vector<glm::vec3>& base,
                std::vector<PosePositions>& exported)
{
    tinygltf::Primitive& primitive = model.meshes[0].primitives[0];
    std::vector<glm::vec3> displacement(base.size());
    exported.assign(poses.size(), PosePositions(base.size()));
    for (std::size_t t = 0; t < poses.size(); ++t) {
        for (std::size_t j = 0; j < base.size(); ++j) {
            displacement[j] = glm::vec3(poses[t][j] - glm::dvec3(base[j]));
            exported[t][j] = glm::dvec3(base[j]) + glm::dvec3(displacement[j]);
        }
        primitive.targets.push_back({{"POSITION", addVec3Accessor(model, displacement, TINYGLTF_TARGET_ARRAY_BUFFER, true)}});
        model.meshes[0].weights.push_back(0.0);
    }
}

// Keyframe t sets weight t to 1 and every other to 0 (row-major [keyframe][target]).
void addWeightAnimation(tinygltf::Model& model, const std::vector<float>& times)
{
    const std::size_t n = times.size();
    std::vector<float> weights(n * n, 0.0f);
    for (std::size_t t = 0; t < n; ++t)
        weights[t * n + t] = 1.0f;
    tinygltf::AnimationSampler sampler;
    sampler.input = addFloatAccessor(model, times, TINYGLTF_TYPE_SCALAR, true);
    sampler.output = addFloatAccessor(model, weights, TINYGLTF_TYPE_SCALAR, false);
    sampler.interpolation = "STEP";
    tinygltf::AnimationChannel channel;
    channel.sampler = 0;
    channel.target_node = 0;
    channel.target_path = "weights";
    tinygltf::Animation animation;
    animation.name = "poses";
    animation.samplers.push_back(sampler);
    animation.channels.push_back(channel);
    model.animations.push_back(animation);
}

} // namespace

ExportedSkin addMorphTargets(tinygltf::Model& model, const SkinningModel& skinning, const std::vector<float>& times)
{
    ExportedSkin report;
    report.kind = SkinExportKind::MorphTargets;
    addTargets(model, reconstructPoses(skinning), toFloat(skinning.restPositions), report.positions);
    addWeightAnimation(model, times);
    return report;
}

} // namespace trimlab::skinning_gltf
