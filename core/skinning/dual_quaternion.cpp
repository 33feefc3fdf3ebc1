#include "core/skinning/dual_quaternion.h"

#include <cassert>
#include <cmath>

namespace trimlab {

namespace {

glm::dquat scaled(const glm::dquat& q, double s)
{
    return glm::dquat(q.w * s, q.x * s, q.y * s, q.z * s);
}

glm::dquat added(const glm::dquat& a, const glm::dquat& b)
{
    return glm::dquat(a.w + b.w, a.x + b.x, a.y + b.y, a.z + b.z);
}

} // namespace

DualQuaternion dualQuaternionFromRigid(const glm::dquat& rotation, const glm::dvec3& translation)
{
    const glm::dquat r = glm::normalize(rotation);
    const glm::dquat t(0.0, translation.x, translation.y, translation.z);
    return {r, scaled(t * r, 0.5)};
}

DualQuaternion operator*(const DualQuaternion& a, const DualQuaternion& b)
{
    return {a.real * b.real, added(a.real * b.dual, a.dual * b.real)};
}

DualQuaternion normalized(const DualQuaternion& q)
{
    const double length = std::sqrt(glm::dot(q.real, q.real));
    if (!(length > 0.0) || !std::isfinite(length))
        return {};
    const glm::dquat real = scaled(q.real, 1.0 / length);
    glm::dquat dual = scaled(q.dual, 1.0 / length);
    // A unit dual quaternion has q_r · q_d = 0; blending leaves a small component along
    // q_r, which would otherwise scale the motion instead of moving it.
    dual = added(dual, scaled(real, -glm::dot(real, dual)));
    return {real, dual};
}

glm::dvec3 translationOf(const DualQuaternion& q)
{
    const glm::dquat t = q.dual * glm::conjugate(q.real);
    return 2.0 * glm::dvec3(t.x, t.y, t.z);
}

Affine3 toAffine(const DualQuaternion& q)
{
    return {glm::mat3_cast(q.real), translationOf(q)};
}

glm::dvec3 transformPoint(const DualQuaternion& q, const glm::dvec3& p)
{
    return q.real * p + translationOf(q);
}

DualQuaternion blendDualQuaternions(std::span<const DualQuaternion> transforms, std::span<const double> weights,
                                    const DualQuaternion& pivot)
{
    assert(transforms.size() == weights.size());
    DualQuaternion sum{glm::dquat(0.0, 0.0, 0.0, 0.0), glm::dquat(0.0, 0.0, 0.0, 0.0)};
    for (std::size_t i = 0; i < transforms.size(); ++i) {
        const double sign = glm::dot(transforms[i].real, pivot.real) < 0.0 ? -1.0 : 1.0;
        sum.real = added(sum.real, scaled(transforms[i].real, sign * weights[i]));
        sum.dual = added(sum.dual, scaled(transforms[i].dual, sign * weights[i]));
    }
    return normalized(sum);
}

} // namespace trimlab
