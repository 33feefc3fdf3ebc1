#include "core/animation/gltf_animation_clip.h"

#include "core/mesh/mesh_load_error.h"

#include <tiny_gltf.h>

#include <algorithm>

namespace trimlab {

namespace {

std::size_t morphTargetCount(const tinygltf::Model& model, const tinygltf::Node& node)
{
    if (node.mesh < 0 || std::size_t(node.mesh) >= model.meshes.size())
        return 0;
    const tinygltf::Mesh& mesh = model.meshes[std::size_t(node.mesh)];
    return mesh.primitives.empty() ? 0 : mesh.primitives.front().targets.size();
}

bool parsePath(const std::string& text, KeyframePath& path)
{
    if (text == "translation")
        path = KeyframePath::Translation;
    else if (text == "rotation")
        path = KeyframePath::Rotation;
    else if (text == "scale")
        path = KeyframePath::Scale;
    else if (text == "weights")
        path = KeyframePath::Weights;
    else
        return false;
    return true;
}

NodeChannel readChannel(const tinygltf::Model& model, int animation, std::size_t index, const std::string& name)
{
    const tinygltf::AnimationChannel& c = model.animations[std::size_t(animation)].channels[index];
    const std::string element = "animation " + std::to_string(animation) + " channel " + std::to_string(index);
    auto fail = [&](const std::string& reason) { throw MeshLoadError(name, reason, {.line = 0, .element = element}); };
    if (c.target_node < 0 || std::size_t(c.target_node) >= model.nodes.size())
        fail("the target node " + std::to_string(c.target_node) + " does not exist");
    NodeChannel channel;
    channel.node = std::size_t(c.target_node);
    parsePath(c.target_path, channel.path);
    const tinygltf::Node& node = model.nodes[channel.node];
    std::size_t components = channel.path == KeyframePath::Rotation ? 4 : 3;
    if (channel.path == KeyframePath::Weights) {
        components = morphTargetCount(model, node);
        if (components == 0)
            fail("animates the weights of node " + std::to_string(channel.node) + ", which has no morph targets");
    } else if (!node.matrix.empty()) {
        fail("animates node " + std::to_string(channel.node) + ", which gives a matrix; animated nodes must use TRS");
    }
    channel.track = readKeyframeTrack(model, animation, c.sampler, components, channel.path, name);
    return channel;
}

} // namespace

void GltfAnimationClip::apply(double time, std::vector<NodeTransform>& nodes) const
{
    for (const NodeChannel& channel : channels) {
        const std::vector<double> v = channel.track.sample(time);
        NodeTransform& node = nodes[channel.node];
        switch (channel.path) {
        case KeyframePath::Translation:
            node.translation = glm::dvec3(v[0], v[1], v[2]);
            break;
        case KeyframePath::Rotation:
            node.rotation = glm::dquat(v[3], v[0], v[1], v[2]);
            break;
        case KeyframePath::Scale:
            node.scale = glm::dvec3(v[0], v[1], v[2]);
            break;
        case KeyframePath::Weights:
            node.weights = v;
            break;
        }
    }
}

GltfAnimationClip readAnimationClip(const tinygltf::Model& model, int index, const std::string& name)
{
    if (index < 0 || std::size_t(index) >= model.animations.size())
        throw MeshLoadError(name, model.animations.empty()
                                      ? std::string("the file has no animations")
                                      : "animation " + std::to_string(index) + " does not exist (the file has " +
                                            std::to_string(model.animations.size()) + ")");
    const tinygltf::Animation& animation = model.animations[std::size_t(index)];
    GltfAnimationClip clip;
    clip.name = animation.name.empty() ? "animation " + std::to_string(index) : animation.name;
    for (std::size_t c = 0; c < animation.channels.size(); ++c) {
        KeyframePath path;
        if (!parsePath(animation.channels[c].target_path, path))
            continue; // e.g. KHR_animation_pointer targets: not geometry
        clip.channels.push_back(readChannel(model, index, c, name));
        const std::vector<double>& times = clip.channels.back().track.times;
        clip.keyframeTimes.insert(clip.keyframeTimes.end(), times.begin(), times.end());
    }
    if (clip.channels.empty())
        throw MeshLoadError(name, "animates nothing (no translation, rotation, scale or weights channel)",
                            {.line = 0, .element = "animation " + std::to_string(index)});
    std::sort(clip.keyframeTimes.begin(), clip.keyframeTimes.end());
    clip.keyframeTimes.erase(std::unique(clip.keyframeTimes.begin(), clip.keyframeTimes.end()),
                             clip.keyframeTimes.end());
    return clip;
}

} // namespace trimlab
