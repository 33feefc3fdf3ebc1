#pragma once
/// \file
/// One glTF 2.0 animation ("clip"): its channels, each a keyframe track driving one
/// node's translation, rotation, scale or morph weights. Internal to the glTF animation
/// loader.

#include "core/animation/gltf_keyframes.h"
#include "core/animation/gltf_node_transforms.h"

#include <cstddef>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace trimlab {

struct NodeChannel {
    std::size_t node = 0;
    KeyframePath path = KeyframePath::Translation;
    KeyframeTrack track;
};

struct GltfAnimationClip {
    std::string name;                  ///< the animation's name, or "animation N"
    std::vector<NodeChannel> channels; ///< channels with an unknown path are skipped
    std::vector<double> keyframeTimes; ///< every channel's keyframe times, sorted, unique

    /// Writes the value of every channel at `time` (seconds) into `nodes`.
    void apply(double time, std::vector<NodeTransform>& nodes) const;
};

/// Reads animation `index`. Throws MeshLoadError naming the animation and channel for: a
/// missing animation ("animation 2 does not exist (the file has 1)"), a channel whose
/// target node does not exist, an animated node that gives a matrix instead of TRS, weights
/// for a node without morph targets, and every sampler problem (gltf_keyframes.h). A clip
/// without channels is an error too ("animates nothing").
[[nodiscard]] GltfAnimationClip readAnimationClip(const tinygltf::Model& model, int index, const std::string& name);

} // namespace trimlab
