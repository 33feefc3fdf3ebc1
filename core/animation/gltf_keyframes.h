#pragma once
/// \file
/// glTF 2.0 animation samplers: keyframe times and values, evaluated at any time with
/// the sampler's interpolation (STEP, LINEAR with quaternion slerp for rotations,
/// CUBICSPLINE). Internal to the glTF animation loader; includes no tinygltf header.

#include <cstddef>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace trimlab {

struct GltfReadContext;

enum class KeyframeInterpolation { Step, Linear, CubicSpline };

/// What a channel animates: a node's translation, rotation or scale, or a mesh's morph
/// target weights.
enum class KeyframePath { Translation, Rotation, Scale, Weights };

/// One sampler: #K strictly increasing times (seconds) and, per keyframe, `components`
/// values (for CUBICSPLINE: in-tangent, value, out-tangent, each `components` long).
/// `rotation` marks unit quaternions (x, y, z, w), which LINEAR interpolates by slerp
/// along the shorter arc and every interpolation renormalises.
struct KeyframeTrack {
    std::vector<double> times;
    std::vector<double> values;
    std::size_t components = 0;
    KeyframeInterpolation interpolation = KeyframeInterpolation::Linear;
    bool rotation = false;

    /// The value at `time` (`components` numbers). Before the first keyframe the first
    /// value holds, after the last the last value (glTF clamps).
    [[nodiscard]] std::vector<double> sample(double time) const;
};

/// Reads sampler `sampler` of animation `animation` for a channel of `path` with
/// `components` values per keyframe (3 for translation and scale, 4 for rotation, the
/// morph target count for weights). Throws MeshLoadError naming the animation and sampler for: a missing
/// sampler, an unknown interpolation, input that is not a SCALAR of increasing finite
/// times, and output whose count does not match the input (×3 for CUBICSPLINE).
[[nodiscard]] KeyframeTrack readKeyframeTrack(const tinygltf::Model& model, int animation, int sampler,
                                              std::size_t components, KeyframePath path,
                                              const std::string& displayName);

} // namespace trimlab
