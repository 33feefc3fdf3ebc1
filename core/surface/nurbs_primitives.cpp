#include "core/surface/nurbs_primitives.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace trimlab {

namespace {

// A planar rational curve: control points (r, y) with weights, for the profile of a
// surface of revolution; or (cos, sin) for the circle of revolution.
struct PlanarCurve {
    int degree = 2;
    std::vector<double> knots;
    std::vector<double> x, y, w;
    bool closed = false;
};

// The exact rational circle of radius 1 centred at (0, 0), counter-clockwise from (1, 0):
// 9 control points on the circumscribed square, corner weights √2/2, 4 quarter arcs.
PlanarCurve unitCircle()
{
    const double c = std::sqrt(0.5);
    PlanarCurve curve;
    curve.knots = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
    curve.x = {1, 1, 0, -1, -1, -1, 0, 1, 1};
    curve.y = {0, 1, 1, 1, 0, -1, -1, -1, 0};
    curve.w = {1, c, 1, c, 1, c, 1, c, 1};
    curve.closed = true;
    return curve;
}

void requirePositive(double value, const char* function, const char* parameter)
{
    if (!std::isfinite(value) || !(value > 0.0))
        throw std::invalid_argument(std::string(function) + ": " + parameter + " must be a finite number > 0");
}

void requireFinite(const glm::dvec3& center, const char* function)
{
    if (!std::isfinite(center.x) || !std::isfinite(center.y) || !std::isfinite(center.z))
        throw std::invalid_argument(std::string(function) + ": the centre must be finite");
}

// The tensor product of the circle (u, angle φ clockwise from +x seen from +y) with
// `profile` (v, points (r, y)): P_ij = center + (r_j x_i, y_j, −r_j y_i), w_ij = w_i w_j.
NurbsSurface revolve(const glm::dvec3& center, const PlanarCurve& profile, const char* name)
{
    const PlanarCurve circle = unitCircle();
    NurbsSurface s;
    s.name = name;
    s.degreeU = circle.degree;
    s.degreeV = profile.degree;
    s.countU = int(circle.x.size());
    s.countV = int(profile.x.size());
    s.knotsU = circle.knots;
    s.knotsV = profile.knots;
    s.closedU = true;
    s.closedV = profile.closed;
    for (int j = 0; j < s.countV; ++j)
        for (int i = 0; i < s.countU; ++i) {
            const double r = profile.x[std::size_t(j)];
            s.points.push_back(center + glm::dvec3(r * circle.x[std::size_t(i)], profile.y[std::size_t(j)],
                                                   -r * circle.y[std::size_t(i)]));
            s.weights.push_back(circle.w[std::size_t(i)] * profile.w[std::size_t(j)]);
        }
    // r = 0 rows: make the pole points bitwise equal (0 · x may be −0).
    for (int j = 0; j < s.countV; ++j)
        if (profile.x[std::size_t(j)] == 0.0)
            for (int i = 0; i < s.countU; ++i)
                s.points[s.index(i, j)] = center + glm::dvec3(0.0, profile.y[std::size_t(j)], 0.0);
    return s;
}

std::vector<double> uniformClampedKnots(int count, int degree)
{
    std::vector<double> knots;
    const int spans = count - degree;
    for (int k = 0; k <= degree; ++k)
        knots.push_back(0.0);
    for (int k = 1; k < spans; ++k)
        knots.push_back(double(k) / double(spans));
    for (int k = 0; k <= degree; ++k)
        knots.push_back(1.0);
    return knots;
}

} // namespace

NurbsSurface makeNurbsSphere(const glm::dvec3& center, double radius)
{
    requireFinite(center, "makeNurbsSphere");
    requirePositive(radius, "makeNurbsSphere", "the radius");
    // Half of the unit circle, from the south pole (0, −1) through (1, 0) to (0, 1).
    const double c = std::sqrt(0.5);
    PlanarCurve profile;
    profile.knots = {0, 0, 0, 1, 1, 2, 2, 2};
    profile.x = {0, radius, radius, radius, 0};
    profile.y = {-radius, -radius, 0, radius, radius};
    profile.w = {1, c, 1, c, 1};
    return revolve(center, profile, "sphere");
}

NurbsSurface makeNurbsTorus(const glm::dvec3& center, double majorRadius, double minorRadius)
{
    requireFinite(center, "makeNurbsTorus");
    requirePositive(majorRadius, "makeNurbsTorus", "the major radius");
    requirePositive(minorRadius, "makeNurbsTorus", "the minor radius");
    if (!(minorRadius < majorRadius))
        throw std::invalid_argument("makeNurbsTorus: the minor radius must be smaller than the major radius");
    // The tube's cross-section, counter-clockwise in the (r, y) half-plane from the outer
    // equator: the solid lies on its left.
    PlanarCurve profile = unitCircle();
    for (std::size_t k = 0; k < profile.x.size(); ++k) {
        profile.x[k] = majorRadius + minorRadius * profile.x[k];
        profile.y[k] = minorRadius * profile.y[k];
    }
    return revolve(center, profile, "torus");
}

NurbsSurface makeNurbsCylinder(const glm::dvec3& center, double radius, double height)
{
    requireFinite(center, "makeNurbsCylinder");
    requirePositive(radius, "makeNurbsCylinder", "the radius");
    requirePositive(height, "makeNurbsCylinder", "the height");
    PlanarCurve profile;
    profile.degree = 1;
    profile.knots = {0, 0, 1, 1};
    profile.x = {radius, radius};
    profile.y = {-0.5 * height, 0.5 * height};
    profile.w = {1, 1};
    return revolve(center, profile, "cylinder");
}

NurbsSurface makeNurbsCappedTube(const glm::dvec3& center, double radius, double height)
{
    requireFinite(center, "makeNurbsCappedTube");
    requirePositive(radius, "makeNurbsCappedTube", "the radius");
    requirePositive(height, "makeNurbsCappedTube", "the height");
    PlanarCurve profile;
    profile.degree = 1;
    profile.knots = {0, 0, 1, 2, 3, 3};
    profile.x = {0, radius, radius, 0};
    profile.y = {-0.5 * height, -0.5 * height, 0.5 * height, 0.5 * height};
    profile.w = {1, 1, 1, 1};
    return revolve(center, profile, "capped tube");
}

NurbsSurface makeNurbsPatch(const glm::dvec3& center, double sizeX, double sizeZ, int countU, int countV)
{
    requireFinite(center, "makeNurbsPatch");
    requirePositive(sizeX, "makeNurbsPatch", "sizeX");
    requirePositive(sizeZ, "makeNurbsPatch", "sizeZ");
    if (countU < 4 || countU > 1000 || countV < 4 || countV > 1000)
        throw std::invalid_argument("makeNurbsPatch: countU and countV must be in 4..1000 (bicubic)");
    NurbsSurface s;
    s.name = "patch";
    s.degreeU = 3;
    s.degreeV = 3;
    s.countU = countU;
    s.countV = countV;
    s.knotsU = uniformClampedKnots(countU, 3);
    s.knotsV = uniformClampedKnots(countV, 3);
    for (int j = 0; j < countV; ++j)
        for (int i = 0; i < countU; ++i) {
            const double x = sizeX * (double(i) / double(countU - 1) - 0.5);
            const double z = -sizeZ * (double(j) / double(countV - 1) - 0.5);
            s.points.push_back(center + glm::dvec3(x, 0.0, z));
            s.weights.push_back(1.0);
        }
    return s;
}

} // namespace trimlab
