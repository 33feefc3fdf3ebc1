#include "core/animation/gltf_keyframes.h"

#include "core/mesh/gltf_accessor.h"
#include "core/mesh/mesh_load_error.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>

namespace trimlab {

namespace {

std::vector<double> normalizedQuaternion(std::vector<double> q)
{
    const double length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (length > 0.0) {
        for (double& c : q)
            c /= length;
    } else {
        q = {0.0, 0.0, 0.0, 1.0};
    }
    return q;
}

std::vector<double> slerp(std::vector<double> a, std::vector<double> b, double s)
{
    a = normalizedQuaternion(std::move(a));
    b = normalizedQuaternion(std::move(b));
    double cosine = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
    if (cosine < 0.0) { // the shorter arc
        for (double& c : b)
            c = -c;
        cosine = -cosine;
    }
    double wa = 1.0 - s;
    double wb = s;
    if (cosine < 1.0 - 1e-12) {
        const double angle = std::acos(std::min(cosine, 1.0));
        wa = std::sin((1.0 - s) * angle) / std::sin(angle);
        wb = std::sin(s * angle) / std::sin(angle);
    }
    std::vector<double> q(4);
    for (int c = 0; c < 4; ++c)
        q[std::size_t(c)] = wa * a[std::size_t(c)] + wb * b[std::size_t(c)];
    return normalizedQuaternion(std::move(q));
}

} // namespace

std::vector<double> KeyframeTrack::sample(double time) const
{
    const std::size_t n = times.size();
    const std::size_t stride = interpolation == KeyframeInterpolation::CubicSpline ? 3 * components : components;
    const std::size_t valueOffset = interpolation == KeyframeInterpolation::CubicSpline ? components : 0;
    auto value = [&](std::size_t k) {
        const auto begin = values.begin() + std::ptrdiff_t(k * stride + valueOffset);
        return std::vector<double>(begin, begin + std::ptrdiff_t(components));
    };
    if (n == 1 || time <= times.front())
        return rotation ? normalizedQuaternion(value(0)) : value(0);
    if (time >= times.back())
        return rotation ? normalizedQuaternion(value(n - 1)) : value(n - 1);
    const std::size_t k = std::size_t(std::upper_bound(times.begin(), times.end(), time) - times.begin()) - 1;
    const double delta = times[k + 1] - times[k];
    const double s = (time - times[k]) / delta;
    if (interpolation == KeyframeInterpolation::Step)
        return rotation ? normalizedQuaternion(value(k)) : value(k);
    if (interpolation == KeyframeInterpolation::Linear) {
        if (rotation)
            return slerp(value(k), value(k + 1), s);
        std::vector<double> a = value(k);
        const std::vector<double> b = value(k + 1);
        for (std::size_t c = 0; c < components; ++c)
            a[c] += s * (b[c] - a[c]);
        return a;
    }
    // Cubic Hermite spline (glTF 2.0 appendix C): tangents scaled by the interval length.
    const double s2 = s * s;
    const double s3 = s2 * s;
    std::vector<double> result(components);
    for (std::size_t c = 0; c < components; ++c) {
        const double v0 = values[k * stride + components + c];
        const double out0 = values[k * stride + 2 * components + c];
        const double in1 = values[(k + 1) * stride + c];
        const double v1 = values[(k + 1) * stride + components + c];
        result[c] = (2 * s3 - 3 * s2 + 1) * v0 + (s3 - 2 * s2 + s) * delta * out0 + (-2 * s3 + 3 * s2) * v1 +
                    (s3 - s2) * delta * in1;
    }
    return rotation ? normalizedQuaternion(std::move(result)) : result;
}

KeyframeTrack readKeyframeTrack(const tinygltf::Model& model, int animation, int sampler, std::size_t components,
                                KeyframePath path, const std::string& displayName)
{
    const std::string element = "animation " + std::to_string(animation) + " sampler " + std::to_string(sampler);
    auto fail = [&](const std::string& reason) {
        throw MeshLoadError(displayName, reason, {.line = 0, .element = element});
    };
    const tinygltf::Animation& a = model.animations[std::size_t(animation)];
    if (sampler < 0 || std::size_t(sampler) >= a.samplers.size())
        fail("does not exist (the animation has " + std::to_string(a.samplers.size()) + " samplers)");
    const tinygltf::AnimationSampler& s = a.samplers[std::size_t(sampler)];
    KeyframeTrack track;
    track.components = components;
    track.rotation = path == KeyframePath::Rotation;
    if (s.interpolation == "STEP")
        track.interpolation = KeyframeInterpolation::Step;
    else if (s.interpolation == "CUBICSPLINE")
        track.interpolation = KeyframeInterpolation::CubicSpline;
    else if (s.interpolation.empty() || s.interpolation == "LINEAR")
        track.interpolation = KeyframeInterpolation::Linear;
    else
        fail("unknown interpolation '" + s.interpolation + "'");
    const GltfReadContext context{displayName, element};
    track.times = readGltfNumbers(model, s.input, TINYGLTF_TYPE_SCALAR, context);
    if (track.times.empty())
        fail("has no keyframes");
    for (std::size_t k = 1; k < track.times.size(); ++k) {
        if (!(track.times[k] > track.times[k - 1]))
            fail("keyframe times must increase strictly (time " + std::to_string(k) + " is not after time " +
                 std::to_string(k - 1) + ")");
    }
    const int outputType = path == KeyframePath::Weights    ? TINYGLTF_TYPE_SCALAR
                           : path == KeyframePath::Rotation ? TINYGLTF_TYPE_VEC4
                                                            : TINYGLTF_TYPE_VEC3;
    track.values = readGltfNumbers(model, s.output, outputType, context);
    const std::size_t perKey = (track.interpolation == KeyframeInterpolation::CubicSpline ? 3 : 1) * components;
    if (track.values.size() != track.times.size() * perKey)
        fail("has " + std::to_string(track.times.size()) + " keyframe times but " +
             std::to_string(track.values.size()) + " output numbers; expected " +
             std::to_string(track.times.size() * perKey));
    return track;
}

} // namespace trimlab
