// The skin half of skinnedGltf (skinning_gltf.h): JOINTS_0/WEIGHTS_0, the skeleton nodes,
// inverse bind matrices and the TRS animation, and the positions they reproduce.
#include "core/skinning/skinning_gltf_joints.h"
#include "core/skinning/skinning_gltf_parts.h"
#include "core/io/gltf_builder.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <cstdint>

namespace trimlab::skinning_gltf {

namespace {

// The weights as written: floats whose sum is 1 as closely as float allows (the largest
// weight, first, takes the rounding), unused slots 0. Influences whose weight is 0 as a
// float are dropped (the validator warns about joints used with zero weight).
SkinningWeights writtenWeights(const SkinningWeights& weights)
{
    SkinningWeights written = weights;
    for (VertexInfluences& in : written.vertices) {
        double rest = 0.0;
        for (std::uint32_t i = 1; i < in.count; ++i) {
            in.weights[i] = double(float(in.weights[i]));
            if (in.weights[i] == 0.0) {
                in.count = i; // sorted by decreasing weight: the rest are 0 as well
                break;
            }
            rest += in.weights[i];
        }
        in.weights[0] = double(float(1.0 - rest));
        for (std::size_t i = in.count; i < kMaxInfluences; ++i) {
            in.bones[i] = 0;
            in.weights[i] = 0.0;
        }
    }
    return written;
}

// JOINTS_0/WEIGHTS_0, and JOINTS_1/WEIGHTS_1 only when some vertex has more than 4
// influences (so a 4-influence skin plays in viewers that read only the first set).
void addJointAttributes(tinygltf::Model& model, const SkinningWeights& written)
{
    std::uint32_t most = 0;
    for (const VertexInfluences& in : written.vertices)
        most = std::max(most, in.count);
    const std::size_t sets = most > 4 ? 2 : 1;
    tinygltf::Primitive& primitive = model.meshes[0].primitives[0];
    for (std::size_t set = 0; set < sets; ++set) {
        std::vector<std::uint16_t> joints;
        std::vector<float> weights;
        for (const VertexInfluences& in : written.vertices)
            for (std::size_t i = 4 * set; i < 4 * set + 4; ++i) {
                joints.push_back(std::uint16_t(in.bones[i]));
                weights.push_back(float(in.weights[i]));
            }
        const std::string suffix = std::to_string(set);
        const int jointView = io::addGltfBufferView(model, joints.data(), joints.size() * sizeof(std::uint16_t),
                                                    TINYGLTF_TARGET_ARRAY_BUFFER);
        primitive.attributes["JOINTS_" + suffix] = io::addGltfAccessor(
            model, jointView, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_VEC4, written.vertices.size());
        const int weightView =
            io::addGltfBufferView(model, weights.data(), weights.size() * sizeof(float), TINYGLTF_TARGET_ARRAY_BUFFER);
        primitive.attributes["WEIGHTS_" + suffix] = io::addGltfAccessor(
            model, weightView, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, written.vertices.size());
    }
}

// Node 1 "skeleton" with the joints 2 … B+1 as children; skin 0 on node 0.
void addSkeleton(tinygltf::Model& model, const std::vector<glm::vec3>& pivots)
{
    tinygltf::Node root;
    root.name = "skeleton";
    tinygltf::Skin skin;
    skin.name = "bones";
    skin.skeleton = int(model.nodes.size());
    std::vector<float> inverseBind;
    for (std::size_t b = 0; b < pivots.size(); ++b) {
        const int node = int(model.nodes.size() + 1 + b);
        root.children.push_back(node);
        skin.joints.push_back(node);
        const std::array<float, 16> m = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -pivots[b].x, -pivots[b].y, -pivots[b].z,
                                         1};
        inverseBind.insert(inverseBind.end(), m.begin(), m.end());
    }
    skin.inverseBindMatrices = io::addGltfFloatAccessor(model, inverseBind, TINYGLTF_TYPE_MAT4, false);
    model.scenes[0].nodes.push_back(int(model.nodes.size()));
    model.nodes.push_back(root);
    for (std::size_t b = 0; b < pivots.size(); ++b) {
        tinygltf::Node joint;
        joint.name = "bone_" + std::to_string(b);
        joint.translation = {pivots[b].x, pivots[b].y, pivots[b].z};
        model.nodes.push_back(joint);
    }
    model.skins.push_back(skin);
    model.nodes[0].skin = 0;
}

// Per joint the written translation (R·c + t) and rotation keyframes, rounded to float;
// `exported` receives the rigid motions those floats stand for.
struct JointTracks {
    std::vector<std::vector<float>> translations; // B × (#P·3)
    std::vector<std::vector<float>> rotations;    // B × (#P·4), x y z w
};

JointTracks jointTracks(const RigidJointAnimation& joints, const std::vector<glm::vec3>& pivots,
                        RigidJointAnimation& exported)
{
    const std::size_t bones = pivots.size();
    JointTracks tracks{std::vector<std::vector<float>>(bones), std::vector<std::vector<float>>(bones)};
    exported.pivots.assign(pivots.begin(), pivots.end());
    exported.poses.assign(joints.poses.size(), std::vector<RigidJointPose>(bones));
    for (std::size_t b = 0; b < bones; ++b) {
        glm::dquat previous(1.0, 0.0, 0.0, 0.0);
        for (std::size_t t = 0; t < joints.poses.size(); ++t) {
            glm::dquat q = joints.poses[t][b].rotation;
            if (glm::dot(q, previous) < 0.0)
                q = -q; // slerp between keyframes takes the short way
            previous = q;
            const glm::dvec3 pivot(pivots[b]);
            const glm::vec3 node(q * pivot + joints.poses[t][b].translation);
            if (!std::isfinite(glm::dot(node, node)) || !std::isfinite(glm::dot(q, q)))
                throw std::runtime_error("skinned glTF export: bone " + std::to_string(b) +
                                         " has no finite rigid "
                                         "motion at pose " +
                                         std::to_string(t));
            const glm::quat qf(q);
            tracks.translations[b].insert(tracks.translations[b].end(), {node.x, node.y, node.z});
            tracks.rotations[b].insert(tracks.rotations[b].end(), {qf.x, qf.y, qf.z, qf.w});
            const glm::dquat written = glm::normalize(glm::dquat(qf));
            exported.poses[t][b] = {written, glm::dvec3(node) - written * pivot};
        }
    }
    return tracks;
}

void addAnimation(tinygltf::Model& model, const JointTracks& tracks, const std::vector<float>& times, bool step)
{
    tinygltf::Animation animation;
    animation.name = "skinning";
    const int input = io::addGltfFloatAccessor(model, times, TINYGLTF_TYPE_SCALAR, true);
    auto channel = [&](int node, const char* path, const std::vector<float>& values, int type) {
        tinygltf::AnimationSampler sampler;
        sampler.input = input;
        sampler.output = io::addGltfFloatAccessor(model, values, type, false);
        sampler.interpolation = step ? "STEP" : "LINEAR";
        tinygltf::AnimationChannel c;
        c.sampler = int(animation.samplers.size());
        c.target_node = node;
        c.target_path = path;
        animation.samplers.push_back(sampler);
        animation.channels.push_back(c);
    };
    for (std::size_t b = 0; b < tracks.translations.size(); ++b) {
        const int node = model.skins[0].joints[b];
        channel(node, "translation", tracks.translations[b], TINYGLTF_TYPE_VEC3);
        channel(node, "rotation", tracks.rotations[b], TINYGLTF_TYPE_VEC4);
    }
    model.animations.push_back(animation);
}

// An LBS model whose every matrix is a rotation plus translation (the rigid decomposition,
// skinning_decomposition.h) is exported as it is, not approximated.
bool hasRigidMatrices(const SkinningModel& skinning)
{
    for (const std::vector<Affine3>& pose : skinning.affine)
        for (const Affine3& m : pose) {
            const glm::dmat3 gram = glm::transpose(m.linear) * m.linear;
            for (int c = 0; c < 3; ++c)
                for (int r = 0; r < 3; ++r)
                    if (std::abs(gram[c][r] - (r == c ? 1.0 : 0.0)) > 1e-9)
                        return false;
            if (glm::determinant(m.linear) < 0.0)
                return false;
        }
    return true;
}

} // namespace

ExportedSkin addSkin(tinygltf::Model& model, const SkinningModel& skinning, const std::vector<PosePositions>& target,
                     const std::vector<float>& times, bool step)
{
    const RigidJointAnimation joints = rigidJointAnimation(skinning, target);
    const std::vector<glm::vec3> pivots = toFloat(joints.pivots);
    const SkinningWeights written = writtenWeights(skinning.weights);
    addJointAttributes(model, written);
    addSkeleton(model, pivots);
    RigidJointAnimation exported;
    addAnimation(model, jointTracks(joints, pivots, exported), times, step);
    ExportedSkin report;
    report.kind = skinning.method == SkinningMethod::Dqs || hasRigidMatrices(skinning)
                      ? SkinExportKind::RigidTransforms
                      : SkinExportKind::RigidApproximation;
    report.joints = skinning.boneCount();
    const std::vector<glm::vec3> rest = toFloat(skinning.restPositions);
    report.positions = rigidSkinPositions(std::vector<glm::dvec3>(rest.begin(), rest.end()), written, exported);
    return report;
}

} // namespace trimlab::skinning_gltf
