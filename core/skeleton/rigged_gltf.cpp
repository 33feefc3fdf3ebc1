#include "core/skeleton/rigged_gltf.h"

#include "core/skeleton/bone_names.h"

#include "core/skinning/skinning_gltf_parts.h"
#include "core/io/gltf_builder.h"
#include "core/skeleton/rig_validation.h"
#include "core/io/atomic_write.h"
#include "core/io/file_extension.h"

#include <tiny_gltf.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>

namespace trimlab {

namespace {

[[noreturn]] void fail(const std::string& what)
{
    throw std::invalid_argument("rigged glTF export: " + what);
}

void requireExportable(const TriangleMesh& mesh, const SkeletonRig& rig, const BoneWeights& weights)
{
    if (mesh.triangles.empty())
        fail("the mesh has no triangles");
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const glm::vec3& p = mesh.positions[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            fail("vertex " + std::to_string(v) + " has a non-finite position");
    }
    for (std::size_t f = 0; f < mesh.triangleCount(); ++f)
        if (std::max({mesh.triangles[f].x, mesh.triangles[f].y, mesh.triangles[f].z}) >= mesh.vertexCount())
            fail("triangle " + std::to_string(f) + " names a vertex ≥ " + std::to_string(mesh.vertexCount()));
    requireValidRig(rig, "rigged glTF export");
    if (rig.bones.empty() || rig.bones.size() > 65535)
        fail(std::to_string(rig.bones.size()) + " bones; a skin holds 1 to 65535 joints");
    if (weights.vertexCount() != mesh.vertexCount() || weights.weights.size() != mesh.vertexCount())
        fail(std::to_string(weights.vertexCount()) + " weighted vertices for " + std::to_string(mesh.vertexCount()));
}

// One vertex's influences as written: used slots (weight > 0) first, unused ones joint 0
// and weight 0; the float sum of the used weights, accumulated in float in slot order as
// the Khronos validator does, is 1 within 1e-7 (its tolerance is 2e-7 per used weight).
void writtenInfluences(std::size_t vertex, const std::array<int, kBoneInfluences>& bones,
                       const std::array<float, kBoneInfluences>& weights, std::size_t boneCount,
                       std::array<std::uint16_t, kBoneInfluences>& joints, std::array<float, kBoneInfluences>& written)
{
    joints.fill(0);
    written.fill(0.0f);
    std::size_t used = 0;
    for (std::size_t k = 0; k < kBoneInfluences; ++k) {
        if (!(weights[k] > 0.0f) || bones[k] < 0)
            continue;
        if (std::size_t(bones[k]) >= boneCount || !std::isfinite(weights[k]))
            fail("vertex " + std::to_string(vertex) + " names bone " + std::to_string(bones[k]) + " of " +
                 std::to_string(boneCount) + " (or a non-finite weight)");
        joints[used] = std::uint16_t(bones[k]);
        written[used++] = weights[k];
    }
    if (used == 0)
        fail("vertex " + std::to_string(vertex) + " has no influence with a positive weight");
    // Divided by their sum (weights that do not quite sum to 1 keep their ratios); the
    // largest weight takes the rounding.
    double total = 0.0;
    for (std::size_t k = 0; k < used; ++k)
        total += double(written[k]);
    const std::size_t largest =
        std::size_t(std::max_element(written.begin(), written.begin() + used) - written.begin());
    double others = 0.0;
    for (std::size_t k = 0; k < used; ++k)
        if (k != largest) {
            written[k] = float(double(written[k]) / total);
            others += double(written[k]);
        }
    written[largest] = float(1.0 - others);
    for (int step = 0; step < 16; ++step) {
        float sum = 0.0f;
        for (std::size_t k = 0; k < used; ++k)
            sum += written[k];
        if (std::abs(double(sum) - 1.0) <= 1e-7)
            break;
        written[largest] = std::nextafter(written[largest], sum > 1.0f ? 0.0f : 2.0f);
    }
}

void addSkinAttributes(tinygltf::Model& model, const BoneWeights& weights, std::size_t boneCount)
{
    std::vector<std::uint16_t> joints;
    std::vector<float> values;
    joints.reserve(kBoneInfluences * weights.vertexCount());
    values.reserve(kBoneInfluences * weights.vertexCount());
    std::array<std::uint16_t, kBoneInfluences> j{};
    std::array<float, kBoneInfluences> w{};
    for (std::size_t v = 0; v < weights.vertexCount(); ++v) {
        writtenInfluences(v, weights.bones[v], weights.weights[v], boneCount, j, w);
        joints.insert(joints.end(), j.begin(), j.end());
        values.insert(values.end(), w.begin(), w.end());
    }
    tinygltf::Primitive& primitive = model.meshes[0].primitives[0];
    const int jointView = io::addGltfBufferView(model, joints.data(), joints.size() * sizeof(std::uint16_t),
                                                TINYGLTF_TARGET_ARRAY_BUFFER);
    primitive.attributes["JOINTS_0"] = io::addGltfAccessor(model, jointView, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                                           TINYGLTF_TYPE_VEC4, weights.vertexCount());
    const int weightView =
        io::addGltfBufferView(model, values.data(), values.size() * sizeof(float), TINYGLTF_TARGET_ARRAY_BUFFER);
    primitive.attributes["WEIGHTS_0"] = io::addGltfAccessor(model, weightView, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                                            TINYGLTF_TYPE_VEC4, weights.vertexCount());
}

// Unit normals as the validator requires them; +Z where the mesh gives none.
std::vector<glm::vec3> exportNormals(const TriangleMesh& mesh)
{
    std::vector<glm::vec3> normals = vertexNormals(mesh);
    for (glm::vec3& n : normals)
        if (!(std::abs(glm::length(n) - 1.0f) < 1e-5f))
            n = glm::vec3(0.0f, 0.0f, 1.0f);
    return normals;
}

tinygltf::Model meshModel(const TriangleMesh& mesh)
{
    tinygltf::Model model;
    model.asset.generator = "TrimLab skeleton export";
    model.buffers.emplace_back();
    tinygltf::Primitive primitive;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.attributes["POSITION"] =
        io::addGltfVec3Accessor(model, mesh.positions, TINYGLTF_TARGET_ARRAY_BUFFER, true);
    primitive.attributes["NORMAL"] =
        io::addGltfVec3Accessor(model, exportNormals(mesh), TINYGLTF_TARGET_ARRAY_BUFFER, false);
    primitive.indices = io::addGltfTriangleIndices(model, mesh.triangles);
    io::addGltfSingleMeshScene(model, primitive, "mesh", 0);
    return model;
}

// A rest frame: the world matrix T(position)·R(rotation) of eq. 15.
struct Frame {
    glm::dvec3 position{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
};

// Frame 0: the root joint; frame 1 + b: the joint node of bone b.
std::vector<Frame> restFrames(const SkeletonRig& rig)
{
    std::vector<Frame> frames(1 + rig.bones.size());
    frames[0].position = rig.joints[std::size_t(rig.root)];
    for (std::size_t b = 0; b < rig.bones.size(); ++b) {
        const glm::dvec3 head = rig.joints[std::size_t(rig.bones[b].head)];
        frames[1 + b] = {head, boneOrientation(head, rig.joints[std::size_t(rig.bones[b].tail)])};
    }
    return frames;
}

std::size_t parentFrame(const SkeletonRig& rig, std::size_t bone)
{
    return rig.bones[bone].parentBone < 0 ? 0 : 1 + std::size_t(rig.bones[bone].parentBone);
}

// Rounded to float, as the file stores it.
glm::dvec3 asFloat(const glm::dvec3& v)
{
    return glm::dvec3(glm::vec3(v));
}

glm::dquat asFloat(const glm::dquat& q)
{
    return glm::dquat(glm::normalize(glm::quat(q)));
}

glm::dmat4 trsMatrix(const glm::dvec3& translation, const glm::dquat& rotation)
{
    return glm::translate(glm::dmat4(1.0), translation) * glm::mat4_cast(rotation);
}

// The inverse bind matrix of a joint, inverted from its world matrix as written.
void appendInverseBind(std::vector<float>& inverseBind, const glm::dmat4& world)
{
    const glm::mat4 ibm(glm::inverse(world));
    const float* m = &ibm[0][0];
    inverseBind.insert(inverseBind.end(), m, m + 16);
}

// Writes the local TRS (eq. 16: M_L = M_W(parent)⁻¹·M_W) of every node and returns the
// inverse bind matrices in skin order (the bones, then the root joint), inverted from the
// world matrices of the written floats.
std::vector<float> addJointNodes(tinygltf::Model& model, const SkeletonRig& rig, const std::vector<Frame>& frames)
{
    const int firstJoint = int(model.nodes.size()) + 1;
    std::vector<glm::dmat4> world(frames.size());
    tinygltf::Node root;
    root.name = "root";
    const glm::dvec3 rootPosition = asFloat(frames[0].position);
    root.translation = {rootPosition.x, rootPosition.y, rootPosition.z};
    world[0] = trsMatrix(rootPosition, glm::dquat(1.0, 0.0, 0.0, 0.0));
    std::vector<tinygltf::Node> joints(rig.bones.size());
    const std::vector<std::string> names = boneNames(rig);
    std::vector<float> inverseBind;
    for (std::size_t b = 0; b < rig.bones.size(); ++b) {
        const Frame& parent = frames[parentFrame(rig, b)];
        const glm::dquat toParent = glm::conjugate(parent.rotation);
        const glm::dvec3 t = asFloat(toParent * (frames[1 + b].position - parent.position));
        const glm::dquat r = asFloat(toParent * frames[1 + b].rotation);
        joints[b].name = names[b];
        joints[b].translation = {t.x, t.y, t.z};
        joints[b].rotation = {r.x, r.y, r.z, r.w};
        world[1 + b] = world[parentFrame(rig, b)] * trsMatrix(t, r);
        appendInverseBind(inverseBind, world[1 + b]);
        const int node = firstJoint + int(b);
        (rig.bones[b].parentBone < 0 ? root : joints[std::size_t(rig.bones[b].parentBone)]).children.push_back(node);
    }
    appendInverseBind(inverseBind, world[0]);
    model.scenes[0].nodes.push_back(int(model.nodes.size()));
    model.nodes.push_back(root);
    model.nodes.insert(model.nodes.end(), joints.begin(), joints.end());
    return inverseBind;
}

// The root joint is a joint of the skin (listed last, so JOINTS_0 value b still means
// bone b; no vertex is bound to it): a joint hierarchy under a non-joint node carrying
// the root's translation imports in Blender with that translation as a pose on every
// root bone, so clearing the pose moved the whole character.
void addSkin(tinygltf::Model& model, const SkeletonRig& rig)
{
    tinygltf::Skin skin;
    skin.name = "skeleton";
    skin.skeleton = int(model.nodes.size());
    const std::vector<float> inverseBind = addJointNodes(model, rig, restFrames(rig));
    for (std::size_t b = 0; b < rig.bones.size(); ++b)
        skin.joints.push_back(skin.skeleton + 1 + int(b));
    skin.joints.push_back(skin.skeleton);
    skin.inverseBindMatrices = io::addGltfFloatAccessor(model, inverseBind, TINYGLTF_TYPE_MAT4, false);
    model.skins.push_back(skin);
}

void addChannel(tinygltf::Model& model, tinygltf::Animation& animation, int input, int node, const char* path,
                const std::vector<float>& values, int type)
{
    tinygltf::AnimationSampler sampler;
    sampler.input = input;
    sampler.output = io::addGltfFloatAccessor(model, values, type, false);
    sampler.interpolation = "LINEAR";
    tinygltf::AnimationChannel channel;
    channel.sampler = int(animation.samplers.size());
    channel.target_node = node;
    channel.target_path = path;
    animation.samplers.push_back(sampler);
    animation.channels.push_back(channel);
}

// Keyframe 0 s: rest; 1 s: the pose. A posed joint's world frame is its bone's motion
// applied to its rest frame, so its local rotation is R_parent⁻¹·R(q_b)·R_b and its local
// translation does not change; the root joint moves by rootTranslation.
void addPoseAnimation(tinygltf::Model& model, const SkeletonRig& rig, const SkeletonPose& pose)
{
    (void)boneMotions(rig, pose); // validates the pose against the rig
    const std::vector<Frame> frames = restFrames(rig);
    tinygltf::Animation animation;
    animation.name = "pose";
    const int input = io::addGltfFloatAccessor(model, {0.0f, 1.0f}, TINYGLTF_TYPE_SCALAR, true);
    const int rootNode = model.skins[0].skeleton;
    const glm::vec3 rest(frames[0].position), moved(frames[0].position + pose.rootTranslation);
    addChannel(model, animation, input, rootNode, "translation", {rest.x, rest.y, rest.z, moved.x, moved.y, moved.z},
               TINYGLTF_TYPE_VEC3);
    for (std::size_t b = 0; b < rig.bones.size(); ++b) {
        const glm::dquat toParent = glm::conjugate(frames[parentFrame(rig, b)].rotation);
        const glm::dquat atRest = asFloat(toParent * frames[1 + b].rotation);
        glm::dquat posed = asFloat(toParent * glm::normalize(pose.rotations[b]) * frames[1 + b].rotation);
        if (glm::dot(posed, atRest) < 0.0)
            posed = -posed; // slerp takes the short way
        addChannel(model, animation, input, rootNode + 1 + int(b), "rotation",
                   {float(atRest.x), float(atRest.y), float(atRest.z), float(atRest.w), float(posed.x), float(posed.y),
                    float(posed.z), float(posed.w)},
                   TINYGLTF_TYPE_VEC4);
    }
    model.animations.push_back(animation);
}

} // namespace

glm::dquat boneOrientation(const glm::dvec3& head, const glm::dvec3& tail)
{
    const glm::dvec3 d = tail - head;
    const double length = glm::length(d);
    if (!(length > 0.0) || !std::isfinite(length))
        return glm::dquat(1.0, 0.0, 0.0, 0.0);
    const glm::dvec3 direction = d / length;
    const double c = direction.y; // dot(+Y, direction)
    if (c < -1.0 + 1e-12)
        return glm::dquat(0.0, 1.0, 0.0, 0.0); // π about +X
    // The half-way quaternion: (1 + c, +Y × direction), normalised.
    return glm::normalize(glm::dquat(1.0 + c, direction.z, 0.0, -direction.x));
}

std::string riggedGltf(const TriangleMesh& mesh, const SkeletonRig& rig, const BoneWeights& weights, bool binary,
                       const RiggedGltfOptions& options)
{
    requireExportable(mesh, rig, weights);
    tinygltf::Model model = meshModel(mesh);
    addSkinAttributes(model, weights, rig.bones.size());
    addSkin(model, rig);
    if (options.pose)
        addPoseAnimation(model, rig, *options.pose);
    std::ostringstream out;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, out, !binary, binary))
        throw std::runtime_error("tinygltf could not serialise the rigged mesh");
    return out.str();
}

void exportRiggedGltf(const TriangleMesh& mesh, const SkeletonRig& rig, const BoneWeights& weights,
                      const std::filesystem::path& path, const RiggedGltfOptions& options)
{
    io::writeFileAtomically(path, riggedGltf(mesh, rig, weights, io::lowercaseExtension(path) == ".glb", options));
}

} // namespace trimlab
