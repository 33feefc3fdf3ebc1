#include "core/mesh/triangle_mesh.h"

#include "core/mesh/corner_angle.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace trimlab {

double Bounds::radius() const
{
    return valid() ? 0.5 * glm::length(max - min) : 0.0;
}

void Bounds::extend(const glm::dvec3& p)
{
    min = glm::min(min, p);
    max = glm::max(max, p);
}

void Bounds::extend(const Bounds& other)
{
    if (!other.valid())
        return;
    extend(other.min);
    extend(other.max);
}

Bounds computeBounds(const TriangleMesh& mesh)
{
    Bounds b;
    for (const glm::vec3& p : mesh.positions) {
        if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))
            b.extend(glm::dvec3(p));
    }
    return b;
}

std::vector<glm::vec3> vertexNormals(const TriangleMesh& mesh)
{
    std::vector<glm::dvec3> sum(mesh.positions.size(), glm::dvec3(0.0));
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::dvec3 p[3] = {glm::dvec3(mesh.positions[t[0]]), glm::dvec3(mesh.positions[t[1]]),
                                 glm::dvec3(mesh.positions[t[2]])};
        const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
        const double len = glm::length(n);
        if (len == 0.0 || !std::isfinite(len))
            continue;
        const glm::dvec3 unit = n / len;
        for (int i = 0; i < 3; ++i)
            sum[t[i]] += unit * cornerAngle(p[i], p[(i + 1) % 3], p[(i + 2) % 3]);
    }
    std::vector<glm::vec3> normals(sum.size(), glm::vec3(0.0f));
    for (std::size_t i = 0; i < sum.size(); ++i) {
        const double len = glm::length(sum[i]);
        if (len > 0.0)
            normals[i] = glm::vec3(sum[i] / len);
    }
    return normals;
}

void appendMesh(TriangleMesh& mesh, const TriangleMesh& other)
{
    const auto offset = static_cast<unsigned>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), other.positions.begin(), other.positions.end());
    mesh.triangles.reserve(mesh.triangles.size() + other.triangles.size());
    for (const glm::uvec3& t : other.triangles)
        mesh.triangles.push_back(t + glm::uvec3(offset));
}

} // namespace trimlab
