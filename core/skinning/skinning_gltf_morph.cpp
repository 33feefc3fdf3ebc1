// The morph-target half of skinnedGltf (skinning_gltf.h): one target per pose and a STEP
// "weights" channel on the mesh node selecting it.
#include "core/skinning/skinning_gltf_parts.h"

#include "core/io/gltf_builder.h"

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
        primitive.targets.push_back(
            {{"POSITION", io::addGltfVec3Accessor(model, displacement, TINYGLTF_TARGET_ARRAY_BUFFER, true)}});
        model.meshes[0].weights.push_back(0.0);
    }
}

} // namespace

ExportedSkin addMorphTargets(tinygltf::Model& model, const SkinningModel& skinning, const std::vector<float>& times)
{
    ExportedSkin report;
    report.kind = SkinExportKind::MorphTargets;
    addTargets(model, reconstructPoses(skinning), toFloat(skinning.restPositions), report.positions);
    io::addGltfMorphStepAnimation(model, "poses", times, 0);
    return report;
}

} // namespace trimlab::skinning_gltf
