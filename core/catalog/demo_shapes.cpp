#include "core/catalog/demo_shapes.h"

#include "core/scene/shape_generators.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace trimlab {

namespace {

using Shape = PushedSphereShape;

void appendArc(std::vector<glm::dvec2>& polyline, glm::dvec2 center, double radius, double from, double to, int steps)
{
    for (int i = 1; i <= steps; ++i) {
        const double a = from + (to - from) * i / steps;
        polyline.push_back(center + radius * glm::dvec2(std::cos(a), std::sin(a)));
    }
}

// The pushed sphere's meridian as a dense polyline (thousands of points).
std::vector<glm::dvec2> densePushedSphereProfile()
{
    std::vector<glm::dvec2> p{{0.0, -1.0}};
    // Unit sphere from the south pole (angle −π/2) up to the rim.
    const double rimAngle = std::atan2(std::sqrt(1.0 - Shape::rimRadius * Shape::rimRadius), Shape::rimRadius);
    appendArc(p, {0.0, 0.0}, 1.0, -glm::half_pi<double>(), rimAngle, 800);
    // Lip: cubic Bézier leaving the sphere along its tangent, arriving at the wall going down.
    const glm::dvec2 b0 = p.back();
    const glm::dvec2 b1 = b0 + 0.2 * glm::dvec2(-std::sin(rimAngle), std::cos(rimAngle));
    const glm::dvec2 b3{Shape::fingerRadius, Shape::lipBottomY};
    const glm::dvec2 b2 = b3 + glm::dvec2(0.0, 0.25);
    for (int i = 1; i <= 400; ++i) {
        const double s = i / 400.0;
        const double r = 1.0 - s;
        p.push_back(r * r * r * b0 + 3.0 * r * r * s * b1 + 3.0 * r * s * s * b2 + s * s * s * b3);
    }
    // Finger wall down to the tip, then the tip's quarter circle to the axis.
    for (int i = 1; i <= 800; ++i)
        p.push_back({Shape::fingerRadius, Shape::lipBottomY + (Shape::fingerBottomY - Shape::lipBottomY) * i / 800.0});
    appendArc(p, {0.0, Shape::fingerBottomY}, Shape::fingerRadius, 0.0, -glm::half_pi<double>(), 400);
    p.back() = {0.0, Shape::fingerTipY};
    return p;
}

// Resamples a polyline at `samples` points evenly spaced in arc length + w · turning.
std::vector<glm::dvec2> resampleByLengthAndTurning(const std::vector<glm::dvec2>& dense, int samples,
                                                   double turningWeight)
{
    std::vector<double> cost(dense.size(), 0.0);
    for (std::size_t i = 1; i < dense.size(); ++i) {
        const glm::dvec2 d = dense[i] - dense[i - 1];
        double turning = 0.0;
        if (i >= 2) {
            const glm::dvec2 e = dense[i - 1] - dense[i - 2];
            turning = std::abs(std::atan2(e.x * d.y - e.y * d.x, glm::dot(e, d)));
        }
        cost[i] = cost[i - 1] + glm::length(d) + turningWeight * turning;
    }
    std::vector<glm::dvec2> out{dense.front()};
    std::size_t segment = 1;
    for (int k = 1; k + 1 < samples; ++k) {
        const double target = cost.back() * k / (samples - 1);
        while (cost[segment] < target)
            ++segment;
        const double s = (target - cost[segment - 1]) / (cost[segment] - cost[segment - 1]);
        out.push_back(glm::mix(dense[segment - 1], dense[segment], s));
    }
    out.push_back(dense.back());
    return out;
}

} // namespace

std::vector<glm::dvec2> pushedSphereProfile(int samples)
{
    return resampleByLengthAndTurning(densePushedSphereProfile(), std::max(samples, 8), 0.5);
}

TriangleMesh makePushedSphere(int segments, int profileSamples)
{
    const std::vector<glm::dvec2> profile = pushedSphereProfile(profileSamples);
    return makeSurfaceOfRevolution(profile, segments);
}

std::vector<glm::dvec3> lemniscateCurve(int samples)
{
    samples = std::max(samples, 8);
    std::vector<glm::dvec3> curve;
    for (int i = 0; i < samples; ++i) {
        const double s = 2.0 * glm::pi<double>() * i / samples;
        curve.push_back({1.6 * std::cos(s), 0.0, 0.7 * std::sin(2.0 * s)});
    }
    return curve;
}

TriangleMesh makeCrossingLoop(int curveSamples, int sides)
{
    const std::vector<glm::dvec3> curve = lemniscateCurve(curveSamples);
    return makeTube(curve, 0.3, sides);
}

} // namespace trimlab
