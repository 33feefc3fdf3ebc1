#pragma once
/// \file
/// The transform a user edits for one scene object: a translation, a rotation given as
/// three angles in degrees and a uniform scale. Its model matrix is always orientation
/// preserving (SceneObject's requirement), so facing and winding keep their meaning.

#include "core/mesh/triangle_mesh.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <optional>

namespace trimlab {

/// model = T(translation) · Rz(z) · Ry(y) · Rx(x) · S(scale): the object is scaled about
/// its own origin, rotated about the world x axis first, then y, then z (right-handed,
/// counter-clockwise looking down the axis), then moved. Angles in degrees.
struct ObjectTransform {
    glm::dvec3 translation{0.0};
    glm::dvec3 rotationDegrees{0.0};
    double scale = 1.0;

    /// The smallest scale modelMatrix() applies; smaller, zero, negative or non-finite
    /// scales are raised to it (a mirror or collapse would break the winding's meaning).
    static constexpr double kMinScale = 1e-6;

    /// The model matrix. Non-finite translation or angle components count as 0.
    [[nodiscard]] glm::dmat4 modelMatrix() const;
    [[nodiscard]] bool isIdentity() const { return *this == ObjectTransform{}; }

    friend bool operator==(const ObjectTransform&, const ObjectTransform&) = default;
};

/// The ObjectTransform whose modelMatrix() equals `model` within `tolerance` (relative to
/// the matrix's scale, per entry), with angles x, z in (−180, 180] and y in [−90, 90]
/// (at y = ±90° the x angle is 0 and z carries the rotation). nullopt when `model` is not
/// such a transform: a projective last row, a non-uniform scale, shear, a mirror or a
/// non-finite entry.
[[nodiscard]] std::optional<ObjectTransform> decomposeObjectTransform(const glm::dmat4& model, double tolerance = 1e-9);

/// The model matrix that places an object whose own bounds are `bounds` with their centre
/// at `center`, scaled uniformly so that their largest side is `size` (a composed
/// benchmark scene: operands of one size crossing each other). `bounds` must not be empty.
[[nodiscard]] glm::dmat4 fitIntoCube(const Bounds& bounds, const glm::dvec3& center, double size);

} // namespace trimlab
