// Compiled with -ffp-contract=off (see core/trim/CMakeLists.txt): the watertightness argument
// needs every vertex sheared by the same rounded operations in every triangle, and the
// exact sign code needs plain IEEE additions and products.
#include "core/trim/ray_triangle.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace trimlab {

namespace {

constexpr double kUnitRoundoff = std::numeric_limits<double>::epsilon() * 0.5;

// s + err == a + b exactly (Knuth's TwoSum).
std::pair<double, double> twoSum(double a, double b)
{
    const double s = a + b;
    const double bb = s - a;
    const double err = (a - (s - bb)) + (b - bb);
    return {s, err};
}

// Exact sign of a sum of doubles: grow a non-overlapping expansion (Shewchuk's
// Grow-Expansion) whose most significant non-zero component carries the sign.
int exactSignOfSum(const double (&terms)[4])
{
    double expansion[4] = {};
    int size = 0;
    for (double b : terms) {
        double q = b;
        for (int i = 0; i < size; ++i) {
            const auto [sum, err] = twoSum(q, expansion[i]);
            expansion[i] = err;
            q = sum;
        }
        expansion[size++] = q;
    }
    for (int i = size - 1; i >= 0; --i) {
        if (expansion[i] != 0.0)
            return expansion[i] > 0.0 ? 1 : -1;
    }
    return 0;
}

int signOf(double x)
{
    return (x > 0.0) - (x < 0.0);
}

// A vertex in the ray's sheared frame: the ray is the +z axis through (0, 0).
struct ShearedVertex {
    double x, y, z;
};

ShearedVertex shear(const WatertightRay& ray, const glm::dvec3& p)
{
    const glm::dvec3 q = p - ray.origin;
    return {q[ray.kx] - ray.shearX * q[ray.kz], q[ray.ky] - ray.shearY * q[ray.kz], ray.scaleZ * q[ray.kz]};
}

// Edge function of the directed edge from -> to at the 2D origin, with its exact sign.
// Swapping from/to negates both exactly, so two triangles sharing an edge agree.
struct EdgeFunction {
    double value;
    int sign;
};

EdgeFunction edgeFunction(const ShearedVertex& from, const ShearedVertex& to)
{
    const double value = to.x * from.y - to.y * from.x;
    return {value, exactSignOfDifferenceOfProducts(to.x, from.y, to.y, from.x)};
}

// Whether the three exact signs describe a hit and, if so, the facing (+1 / -1).
// Zero edges are decided by ownsZeroEdge on the edge oriented as in the normalised
// triangle (inside positive): the edge itself for facing +1, reversed for facing -1.
int hitFacing(const EdgeFunction (&e)[3], const ShearedVertex* const (&from)[3], const ShearedVertex* const (&to)[3])
{
    const bool anyPositive = e[0].sign > 0 || e[1].sign > 0 || e[2].sign > 0;
    const bool anyNegative = e[0].sign < 0 || e[1].sign < 0 || e[2].sign < 0;
    if (anyPositive == anyNegative)
        return 0; // mixed signs (outside) or all zero (edge-on)
    const int facing = anyPositive ? 1 : -1;
    for (int i = 0; i < 3; ++i) {
        if (e[i].sign != 0)
            continue;
        const ShearedVertex& p = facing > 0 ? *from[i] : *to[i];
        const ShearedVertex& q = facing > 0 ? *to[i] : *from[i];
        if (!ownsZeroEdge(p.x, p.y, q.x, q.y))
            return 0;
    }
    return facing;
}

} // namespace

int exactSignOfDifferenceOfProducts(double p, double q, double r, double s)
{
    const double pq = p * q;
    const double rs = r * s;
    const double difference = pq - rs;
    // Each product and the difference round once: the error is below 3u(|pq| + |rs|).
    const double errorBound = 4.0 * kUnitRoundoff * (std::abs(pq) + std::abs(rs));
    if (std::abs(difference) > errorBound)
        return signOf(difference);
    // pq + pqErr == p*q and rs + rsErr == r*s exactly (fma rounds once).
    const double pqErr = std::fma(p, q, -pq);
    const double rsErr = std::fma(r, s, -rs);
    const double terms[4] = {pq, -rs, pqErr, -rsErr};
    return exactSignOfSum(terms);
}

bool ownsZeroEdge(double fromX, double fromY, double toX, double toY)
{
    const double dx = toX - fromX; // the sign of a rounded difference is exact
    const double dy = toY - fromY;
    return dy > 0.0 || (dy == 0.0 && dx < 0.0);
}

WatertightRay makeWatertightRay(const PixelRay& ray)
{
    const glm::dvec3& d = ray.direction;
    const glm::dvec3 absD = glm::abs(d);
    WatertightRay w;
    w.origin = ray.origin;
    w.kz = absD.x >= absD.y ? (absD.x >= absD.z ? 0 : 2) : (absD.y >= absD.z ? 1 : 2);
    w.kx = (w.kz + 1) % 3;
    w.ky = (w.kx + 1) % 3;
    if (d[w.kz] < 0.0) // keep the 2D winding of front-facing triangles positive
        std::swap(w.kx, w.ky);
    w.shearX = d[w.kx] / d[w.kz];
    w.shearY = d[w.ky] / d[w.kz];
    w.scaleZ = 1.0 / d[w.kz];
    return w;
}

std::optional<TriangleHit> intersectTriangle(const WatertightRay& ray, const glm::dvec3& a, const glm::dvec3& b,
                                             const glm::dvec3& c)
{
    const ShearedVertex sa = shear(ray, a);
    const ShearedVertex sb = shear(ray, b);
    const ShearedVertex sc = shear(ray, c);
    // U, V, W: edges b->c, c->a, a->b; the weights of a, b, c.
    const EdgeFunction e[3] = {edgeFunction(sb, sc), edgeFunction(sc, sa), edgeFunction(sa, sb)};
    if (!std::isfinite(e[0].value + e[1].value + e[2].value + sa.z + sb.z + sc.z))
        return std::nullopt; // non-finite vertex or overflow
    const ShearedVertex* const from[3] = {&sb, &sc, &sa};
    const ShearedVertex* const to[3] = {&sc, &sa, &sb};
    const int facing = hitFacing(e, from, to);
    if (facing == 0)
        return std::nullopt;
    // Weights with the facing's sign; a rounded value that disagrees with its exact sign
    // (only possible for values within rounding of zero) is taken as zero.
    double weight[3];
    for (int i = 0; i < 3; ++i)
        weight[i] = signOf(e[i].value) == facing ? std::abs(e[i].value) : 0.0;
    const double det = weight[0] + weight[1] + weight[2];
    TriangleHit hit;
    hit.facing = facing;
    if (det > 0.0 && std::isfinite(det)) {
        hit.u = weight[1] / det;
        hit.v = weight[2] / det;
    } else {
        // A sliver seen almost edge-on whose weights all round to zero: any point of it
        // is as good as another; take the centroid.
        hit.u = hit.v = 1.0 / 3.0;
    }
    hit.t = (1.0 - hit.u - hit.v) * sa.z + hit.u * sb.z + hit.v * sc.z;
    if (!std::isfinite(hit.t))
        return std::nullopt;
    return hit;
}

} // namespace trimlab
