#pragma once
/// \file
/// One intersection of a pixel ray with one scene triangle, as the CPU reference collects
/// them (the CPU twin of a GPU fragment), and the order in which a ray walks them.

#include <tuple>

namespace trimlab {

/// A ray–triangle hit.
/// - `t`: ray parameter of the hit; for a PixelRay this is the view depth (see camera.h).
/// - `objectId`: index into Scene::objects; `primitiveId`: triangle index within that object.
/// - `facing`: +1 when the triangle is front-facing for the ray (counter-clockwise seen from
///   the eye, i.e. dot((b−a)×(c−a), direction) < 0; crossing it enters the solid, w += 1),
///   −1 when back-facing (crossing it exits the solid, w −= 1).
/// - `u`, `v`: barycentric weights of the triangle's 2nd and 3rd vertex; the hit point is
///   (1−u−v)·a + u·b + v·c, with u, v, 1−u−v in [0, 1].
struct RayHit {
    double t = 0.0;
    int objectId = -1;
    int primitiveId = -1;
    int facing = 0;
    double u = 0.0;
    double v = 0.0;
};

/// The order in which a ray walks its hits: by increasing t; ties (coincident surfaces,
/// e.g. a doubly covered sphere) broken by object id, then primitive id, so every backend
/// and every run resolves them the same way. Use with std::sort.
[[nodiscard]] inline bool walkOrder(const RayHit& a, const RayHit& b)
{
    return std::tie(a.t, a.objectId, a.primitiveId) < std::tie(b.t, b.objectId, b.primitiveId);
}

} // namespace trimlab
