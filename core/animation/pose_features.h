#pragma once
/// \file
/// The per-vertex feature a pose is partitioned by (thesis 2.2: "a pose partitioning
/// feature is computed from an animation pose p_t and a reference pose"): the rotation
/// angle θ_v of the deformation gradients, or the vertex velocity or acceleration
/// (thesis 3.2.5).

#include "core/animation/deformation_gradient.h"
#include "core/animation/mesh_animation.h"

#include <cstddef>
#include <string_view>
#include <vector>

namespace trimlab {

enum class FeatureKind {
    RotationAngle, ///< θ_v (radians, 1 value per vertex)
    Velocity,      ///< x_t − x_{t−1} (position units per frame, 3 values per vertex)
    Acceleration,  ///< x_{t+1} − 2·x_t + x_{t−1} (units per frame², 3 values per vertex)
};

/// Which pose the rotation angle is measured against. Velocity and acceleration are
/// differences of neighbouring frames and ignore it.
enum class ReferenceMode {
    Rest,     ///< the animation's rest pose p_0
    Previous, ///< the pose before, p_{t−1}
};

struct FeatureSettings {
    FeatureKind kind = FeatureKind::RotationAngle;
    ReferenceMode reference = ReferenceMode::Rest;
    VertexAveraging averaging = VertexAveraging::Uniform;
};

/// The feature of one pose: #V × `dimension` values, vertex-major.
struct PoseFeature {
    std::size_t pose = 0;
    std::size_t dimension = 1;
    std::vector<double> values;
};

/// The poses (in increasing order) that have a feature and therefore a partition — the
/// thesis's p_1 … p_k: for RotationAngle/Rest every pose but the rest pose (its angle is
/// 0 everywhere); for RotationAngle/Previous and Velocity poses 1 … #P−1; for
/// Acceleration poses 1 … #P−2 (a central difference needs both neighbours). Appending
/// a pose therefore adds exactly one feature pose once there are enough poses.
[[nodiscard]] std::vector<std::size_t> featurePoses(std::size_t poseCount, std::size_t restPose,
                                                    const FeatureSettings& settings);

/// The feature poses whose feature changes when pose `edited` changes (a subset of
/// featurePoses): the pose itself, the next one for differences with the previous pose,
/// both neighbours for acceleration, and every pose when the rest pose changes and the
/// rest pose is the reference.
[[nodiscard]] std::vector<std::size_t> posesAffectedByEdit(std::size_t poseCount, std::size_t restPose,
                                                           std::size_t edited, const FeatureSettings& settings);

/// Computes the feature of `pose`, which must be one of featurePoses (else
/// std::invalid_argument). RotationAngle: faceRotationAngles against the reference pose,
/// combined per vertex by `settings.averaging`.
[[nodiscard]] PoseFeature computePoseFeature(const MeshAnimation& animation, std::size_t pose,
                                             const FeatureSettings& settings);

/// "rotation", "velocity", "acceleration" / "rest", "previous" (command line and JSON).
[[nodiscard]] std::string_view featureName(FeatureKind kind);
[[nodiscard]] std::string_view referenceName(ReferenceMode mode);

} // namespace trimlab
