#include "core/scene/object_transform.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace trimlab {

namespace {

double finiteOrZero(double value)
{
    return std::isfinite(value) ? value : 0.0;
}

/// Rz(z) · Ry(y) · Rx(x) for angles in radians.
glm::dmat3 rotationMatrix(const glm::dvec3& radians)
{
    const glm::dmat4 rz = glm::rotate(glm::dmat4(1.0), radians.z, glm::dvec3(0.0, 0.0, 1.0));
    const glm::dmat4 ry = glm::rotate(glm::dmat4(1.0), radians.y, glm::dvec3(0.0, 1.0, 0.0));
    const glm::dmat4 rx = glm::rotate(glm::dmat4(1.0), radians.x, glm::dvec3(1.0, 0.0, 0.0));
    return glm::dmat3(rz * ry * rx);
}

/// The angles (radians) of a rotation matrix R = Rz · Ry · Rx. glm is column-major:
/// r[c][j] is row j of column c.
glm::dvec3 rotationAngles(const glm::dmat3& r)
{
    const double sinY = std::clamp(-r[0][2], -1.0, 1.0);
    const double y = std::asin(sinY);
    if (std::sqrt(r[0][0] * r[0][0] + r[0][1] * r[0][1]) > 1e-12) {
        // cos y > 0: x from row 2 (cos y · sin x, cos y · cos x), z from column 0.
        return {std::atan2(r[1][2], r[2][2]), y, std::atan2(r[0][1], r[0][0])};
    }
    // Gimbal lock (y = ±90°): only x ∓ z is defined; put it all into z.
    return {0.0, y, std::atan2(-r[1][0], r[1][1])};
}

double largestMagnitude(const glm::dmat4& m)
{
    double largest = 0.0;
    for (int c = 0; c < 4; ++c)
        for (int j = 0; j < 4; ++j)
            largest = std::max(largest, std::abs(m[c][j]));
    return largest;
}

} // namespace

glm::dmat4 ObjectTransform::modelMatrix() const
{
    const double s = std::isfinite(scale) ? std::max(scale, kMinScale) : kMinScale;
    const glm::dvec3 radians{glm::radians(finiteOrZero(rotationDegrees.x)),
                             glm::radians(finiteOrZero(rotationDegrees.y)),
                             glm::radians(finiteOrZero(rotationDegrees.z))};
    glm::dmat4 model(rotationMatrix(radians) * s);
    model[3] = glm::dvec4(finiteOrZero(translation.x), finiteOrZero(translation.y), finiteOrZero(translation.z), 1.0);
    return model;
}

std::optional<ObjectTransform> decomposeObjectTransform(const glm::dmat4& model, double tolerance)
{
    for (int c = 0; c < 4; ++c)
        for (int j = 0; j < 4; ++j)
            if (!std::isfinite(model[c][j]))
                return std::nullopt;
    const glm::dmat3 linear(model);
    const double determinant = glm::determinant(linear);
    if (!(determinant > 0.0))
        return std::nullopt; // a mirror or a collapse
    ObjectTransform transform;
    transform.scale = std::cbrt(determinant);
    transform.translation = glm::dvec3(model[3]);
    transform.rotationDegrees = glm::degrees(rotationAngles(linear / transform.scale));
    // Whatever the angles could not express (shear, non-uniform scale, a projective row)
    // shows as a difference when the transform is rebuilt.
    const glm::dmat4 rebuilt = transform.modelMatrix();
    const double allowed = tolerance * std::max(1.0, largestMagnitude(model));
    for (int c = 0; c < 4; ++c)
        for (int j = 0; j < 4; ++j)
            if (std::abs(rebuilt[c][j] - model[c][j]) > allowed)
                return std::nullopt;
    return transform;
}

glm::dmat4 fitIntoCube(const Bounds& bounds, const glm::dvec3& center, double size)
{
    const glm::dvec3 extent = bounds.max - bounds.min;
    const double scale = size / std::max({extent.x, extent.y, extent.z});
    return glm::scale(glm::translate(glm::dmat4(1.0), center), glm::dvec3(scale)) *
           glm::translate(glm::dmat4(1.0), -bounds.center());
}

} // namespace trimlab
