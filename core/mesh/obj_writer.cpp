#include "core/mesh/obj_writer.h"

#include "core/io/atomic_write.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace trimlab {

namespace {

void appendVector(std::string& out, const char* tag, const glm::vec3& v)
{
    char line[96];
    const int n = std::snprintf(line, sizeof line, "%s %.9g %.9g %.9g\n", tag, double(v.x), double(v.y), double(v.z));
    out.append(line, std::size_t(n));
}

} // namespace

std::string meshObjText(const TriangleMesh& mesh, std::span<const glm::vec3> normals, std::string_view comment)
{
    if (!normals.empty() && normals.size() != mesh.positions.size())
        throw std::invalid_argument("meshObjText: " + std::to_string(normals.size()) + " normals for " +
                                    std::to_string(mesh.positions.size()) + " vertices");
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
        for (int k = 0; k < 3; ++k)
            if (mesh.triangles[f][k] >= mesh.positions.size())
                throw std::invalid_argument("meshObjText: triangle " + std::to_string(f) + " names vertex " +
                                            std::to_string(mesh.triangles[f][k]) + " of " +
                                            std::to_string(mesh.positions.size()));
    std::string out = "# TrimLab\n";
    if (!comment.empty()) {
        std::string line(comment);
        std::replace(line.begin(), line.end(), '\n', ' ');
        std::replace(line.begin(), line.end(), '\r', ' ');
        out += "# " + line + "\n";
    }
    out.reserve(out.size() + mesh.positions.size() * (normals.empty() ? 40 : 80) + mesh.triangles.size() * 40);
    for (const glm::vec3& p : mesh.positions)
        appendVector(out, "v", p);
    for (const glm::vec3& n : normals)
        appendVector(out, "vn", n);
    char line[96];
    for (const glm::uvec3& t : mesh.triangles) {
        const unsigned a = t.x + 1, b = t.y + 1, c = t.z + 1;
        const int n = normals.empty() ? std::snprintf(line, sizeof line, "f %u %u %u\n", a, b, c)
                                      : std::snprintf(line, sizeof line, "f %u//%u %u//%u %u//%u\n", a, a, b, b, c, c);
        out.append(line, std::size_t(n));
    }
    return out;
}

void requireFiniteVertices(const std::filesystem::path& path, const TriangleMesh& mesh)
{
    const auto finite = [](const glm::vec3& p) {
        return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
    };
    const auto first = std::find_if_not(mesh.positions.begin(), mesh.positions.end(), finite);
    if (first == mesh.positions.end())
        return;
    const glm::vec3& p = *first;
    const float bad = !std::isfinite(p.x) ? p.x : !std::isfinite(p.y) ? p.y : p.z;
    throw std::invalid_argument(path.string() + ": vertex " + std::to_string(first - mesh.positions.begin()) +
                                " has a non-finite coordinate (" +
                                (std::isnan(bad) ? "nan"
                                 : bad > 0       ? "inf"
                                                 : "-inf") +
                                "); nothing was written");
}

void saveMeshObj(const std::filesystem::path& path, const TriangleMesh& mesh, std::span<const glm::vec3> normals,
                 std::string_view comment)
{
    requireFiniteVertices(path, mesh);
    io::writeFileAtomically(path, meshObjText(mesh, normals, comment));
}

} // namespace trimlab
