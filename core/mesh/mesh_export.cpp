#include "core/mesh/mesh_export.h"

#include "core/io/file_extension.h"
#include "core/io/atomic_write.h"
#include "core/io/gltf_builder.h"
#include "core/mesh/obj_writer.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <stdexcept>

namespace trimlab {

namespace {

static_assert(std::endian::native == std::endian::little, "the binary writers assume a little-endian machine");

template <class T>
void append(std::string& out, const T& value)
{
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    out.append(bytes, sizeof(T));
}

void checkIndices(const TriangleMesh& mesh)
{
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            if (mesh.triangles[t][k] >= mesh.positions.size())
                throw std::invalid_argument("saveTriangleMesh: triangle " + std::to_string(t) +
                                            " refers to a vertex beyond the mesh");
}

std::string plyBytes(const TriangleMesh& mesh, std::string_view comment)
{
    std::string out = "ply\nformat binary_little_endian 1.0\n";
    if (!comment.empty())
        out += "comment " + std::string(comment) + "\n";
    out += "element vertex " + std::to_string(mesh.positions.size()) +
           "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
           std::to_string(mesh.triangles.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
    for (const glm::vec3& p : mesh.positions)
        for (int k = 0; k < 3; ++k)
            append(out, p[k]);
    for (const glm::uvec3& t : mesh.triangles) {
        append(out, std::uint8_t(3));
        for (int k = 0; k < 3; ++k)
            append(out, std::int32_t(t[k]));
    }
    return out;
}

std::string stlBytes(const TriangleMesh& mesh, std::string_view comment)
{
    // The 80-byte header must not start with "solid" (readers would take it for ASCII).
    std::string header = "TrimLab binary STL";
    if (!comment.empty())
        header += ": " + std::string(comment);
    header.resize(80, ' ');
    std::string out = header;
    append(out, std::uint32_t(mesh.triangles.size()));
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::vec3 a = mesh.positions[t.x], b = mesh.positions[t.y], c = mesh.positions[t.z];
        const glm::vec3 n = glm::cross(b - a, c - a);
        const float length = glm::length(n);
        const glm::vec3 unit = length > 0.0f ? n / length : glm::vec3(0.0f);
        for (const glm::vec3& v : {unit, a, b, c})
            for (int k = 0; k < 3; ++k)
                append(out, v[k]);
        append(out, std::uint16_t(0));
    }
    return out;
}

std::string gltfBytes(const TriangleMesh& mesh, std::string_view comment, bool binary)
{
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = comment.empty() ? std::string("TrimLab") : "TrimLab: " + std::string(comment);
    model.buffers.emplace_back();
    tinygltf::Primitive primitive;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.attributes["POSITION"] =
        io::addGltfVec3Accessor(model, mesh.positions, TINYGLTF_TARGET_ARRAY_BUFFER, true);
    primitive.indices = io::addGltfTriangleIndices(model, mesh.triangles);
    io::addGltfSingleMeshScene(model, primitive, "trimmed solid");
    std::ostringstream out;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, out, !binary, binary))
        throw std::runtime_error("tinygltf could not serialise the mesh");
    return out.str();
}

} // namespace

bool isMeshExportPath(const std::filesystem::path& path)
{
    const std::string ext = io::lowercaseExtension(path);
    return ext == ".obj" || ext == ".ply" || ext == ".stl" || ext == ".gltf" || ext == ".glb";
}

std::string meshExportFormatsText()
{
    return "obj, ply, stl, gltf or glb";
}

void saveTriangleMesh(const std::filesystem::path& path, const TriangleMesh& mesh, std::string_view comment)
{
    const std::string ext = io::lowercaseExtension(path);
    if (ext == ".obj") {
        saveMeshObj(path, mesh, {}, comment);
        return;
    }
    if (!isMeshExportPath(path))
        throw std::invalid_argument(path.string() + ": unknown mesh format '" + ext + "' (use " +
                                    meshExportFormatsText() + ")");
    checkIndices(mesh);
    requireFiniteVertices(path, mesh);
    const std::string bytes = ext == ".ply"   ? plyBytes(mesh, comment)
                              : ext == ".stl" ? stlBytes(mesh, comment)
                                              : gltfBytes(mesh, comment, ext == ".glb");
    io::writeFileAtomically(path, bytes);
}

} // namespace trimlab
