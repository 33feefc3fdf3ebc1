#include "core/view/camera.h"

#include "core/util/parse_numbers.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace trimlab {

glm::dmat4 viewMatrix(const Camera& camera)
{
    return glm::lookAt(camera.eye, camera.target, camera.up);
}

glm::dmat4 projectionMatrix(const Camera& camera, double aspect)
{
    return glm::perspective(glm::radians(camera.fovyDegrees), aspect, camera.zNear, camera.zFar);
}

PixelRay pixelRay(const Camera& camera, int width, int height, int x, int y)
{
    const double aspect = double(width) / double(height);
    const double tanHalf = std::tan(glm::radians(camera.fovyDegrees) * 0.5);
    const double ndcX = (double(x) + 0.5) / double(width) * 2.0 - 1.0;
    const double ndcY = 1.0 - (double(y) + 0.5) / double(height) * 2.0;
    const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::dvec3 up = glm::cross(right, forward);
    const glm::dvec3 dir = forward + right * (ndcX * tanHalf * aspect) + up * (ndcY * tanHalf);
    return {camera.eye, dir};
}

Camera withDepthRange(Camera camera, const Bounds& bounds)
{
    if (!bounds.valid())
        return camera;
    const double radius = std::max(bounds.radius(), 1e-6);
    const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
    const double centerDepth = glm::dot(bounds.center() - camera.eye, forward);
    // 10% margin past the bounding sphere keeps every fragment inside the far plane.
    camera.zFar = std::max(centerDepth + 1.1 * radius, 1e-3 * radius);
    // The near plane hugs the scene from outside but never exceeds a small fraction of
    // the radius when the eye is inside, so the inside stays visible.
    camera.zNear = std::max(centerDepth - 1.1 * radius, 1e-3 * radius);
    camera.zNear = std::min(camera.zNear, 0.5 * camera.zFar);
    return camera;
}

Camera fitCamera(const Bounds& bounds, double aspect, const glm::dvec3& viewDirection)
{
    Camera camera;
    const glm::dvec3 center = bounds.valid() ? bounds.center() : glm::dvec3(0.0);
    const double radius = bounds.valid() ? std::max(bounds.radius(), 1e-6) : 1.0;
    const glm::dvec3 dir = glm::normalize(viewDirection);
    const double halfFovy = glm::radians(camera.fovyDegrees) * 0.5;
    const double halfFov = std::min(halfFovy, std::atan(std::tan(halfFovy) * aspect));
    const double distance = radius / std::sin(halfFov);
    camera.target = center;
    camera.eye = center - dir * distance;
    // Keep "up" usable when looking straight up or down.
    camera.up = std::abs(dir.y) > 0.99 ? glm::dvec3(0.0, 0.0, -1.0) : glm::dvec3(0.0, 1.0, 0.0);
    return withDepthRange(camera, bounds);
}

std::optional<Camera> parseCamera(std::string_view text, std::string* error)
{
    const std::optional<std::vector<double>> v = parseNumberList(text, 10, error);
    if (!v)
        return std::nullopt;
    Camera c;
    c.eye = {(*v)[0], (*v)[1], (*v)[2]};
    c.target = {(*v)[3], (*v)[4], (*v)[5]};
    c.up = {(*v)[6], (*v)[7], (*v)[8]};
    c.fovyDegrees = (*v)[9];
    auto fail = [&](const char* why) {
        if (error)
            *error = why;
        return std::nullopt;
    };
    if (glm::length(c.target - c.eye) == 0.0)
        return fail("camera eye and target coincide");
    if (glm::length(glm::cross(c.target - c.eye, c.up)) == 0.0)
        return fail("camera up vector is zero or parallel to the view direction");
    if (!(c.fovyDegrees > 0.0 && c.fovyDegrees < 180.0))
        return fail("camera fovy must be between 0 and 180 degrees");
    return c;
}

std::string formatCamera(const Camera& c)
{
    std::ostringstream s;
    s.precision(9);
    s << c.eye.x << ',' << c.eye.y << ',' << c.eye.z << ',' << c.target.x << ',' << c.target.y << ',' << c.target.z
      << ',' << c.up.x << ',' << c.up.y << ',' << c.up.z << ',' << c.fovyDegrees;
    return s.str();
}

} // namespace trimlab
