#include "core/mesh/mesh_io.h"

#include "core/io/file_bytes.h"

#include "core/mesh/gltf_reader.h"
#include "core/mesh/mesh_validation.h"
#include "core/mesh/gzip_input.h"
#include "core/mesh/obj_reader.h"
#include "core/mesh/off_reader.h"
#include "core/mesh/ply_reader.h"
#include "core/mesh/stl_reader.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <optional>

namespace trimlab {

namespace {

enum class MeshFormat { Obj, Off, Ply, Stl, Gltf };

constexpr std::array<std::string_view, 6> kExtensions = {"obj", "off", "ply", "stl", "gltf", "glb"};

std::optional<MeshFormat> formatForExtension(std::string_view extension)
{
    if (extension == "obj")
        return MeshFormat::Obj;
    if (extension == "off")
        return MeshFormat::Off;
    if (extension == "ply")
        return MeshFormat::Ply;
    if (extension == "stl")
        return MeshFormat::Stl;
    if (extension == "gltf" || extension == "glb")
        return MeshFormat::Gltf;
    return std::nullopt;
}

std::string toLower(std::string_view text)
{
    std::string lower(text);
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return lower;
}

// A requested format: the extension without dot, lower case, and whether ".gz" was named.
struct FormatRequest {
    std::string extension;
    bool gzipNamed = false;
};

// "obj", ".OBJ", "obj.gz", "mesh.obj.gz" all work: the last extension before an optional ".gz".
FormatRequest parseExtension(std::string_view extension)
{
    std::string text = toLower(extension);
    FormatRequest request;
    if (text.size() >= 3 && text.substr(text.size() - 3) == ".gz") {
        request.gzipNamed = true;
        text.resize(text.size() - 3);
    } else if (text == "gz") {
        request.gzipNamed = true;
        text.clear();
    }
    const std::size_t dot = text.rfind('.');
    request.extension = dot == std::string::npos ? text : text.substr(dot + 1);
    return request;
}

FormatRequest requestForPath(const std::filesystem::path& path)
{
    std::filesystem::path name = path.filename();
    const bool gzipNamed = toLower(name.extension().string()) == ".gz";
    if (gzipNamed)
        name = name.stem();
    FormatRequest request = parseExtension(name.extension().string());
    request.gzipNamed = gzipNamed;
    return request;
}

MeshFormat requireFormat(const FormatRequest& request, const std::string& displayName)
{
    if (const std::optional<MeshFormat> format = formatForExtension(request.extension))
        return *format;
    std::string supported;
    for (const std::string_view e : kExtensions)
        supported += (supported.empty() ? "." : ", .") + std::string(e);
    const std::string what = request.extension.empty() ? "the file name has no mesh extension"
                                                       : "unsupported file extension '." + request.extension + "'";
    throw MeshLoadError(displayName, what + "; supported: " + supported + " (each also as .gz)");
}

TriangleMesh readFormat(MeshFormat format, std::string_view bytes, const std::string& displayName,
                        const std::filesystem::path& baseDir)
{
    switch (format) {
    case MeshFormat::Obj:
        return readObj(bytes, displayName);
    case MeshFormat::Off:
        return readOff(bytes, displayName);
    case MeshFormat::Ply:
        return readPly(bytes, displayName);
    case MeshFormat::Stl:
        return readStl(bytes, displayName);
    case MeshFormat::Gltf:
        return readGltf(bytes, displayName, baseDir);
    }
    throw MeshLoadError(displayName, "internal error: unknown mesh format");
}

TriangleMesh readUsableFormat(MeshFormat format, std::string_view bytes, const std::string& displayName,
                              const std::filesystem::path& baseDir)
{
    // Refused at load what could never be drawn or trimmed (a glTF accessor without a
    // buffer view reads as zeros, for one), rather than rendering an empty picture.
    TriangleMesh mesh = readFormat(format, bytes, displayName, baseDir);
    if (const std::string reason = unusableGeometryReason(mesh); !reason.empty())
        throw MeshLoadError(displayName, reason);
    return mesh;
}

TriangleMesh loadBytes(std::string_view bytes, const FormatRequest& request, const std::string& displayName,
                       const std::filesystem::path& baseDir)
{
    const MeshFormat format = requireFormat(request, displayName);
    if (bytes.empty())
        throw MeshLoadError(displayName, "the file is empty (0 bytes)");
    if (!hasGzipMagic(bytes)) {
        if (request.gzipNamed)
            throw MeshLoadError(displayName, "the file is named .gz but is not gzip data (it does not start with "
                                             "the bytes 1f 8b); rename it or compress it with gzip");
        return readUsableFormat(format, bytes, displayName, baseDir);
    }
    const std::string plain = gunzip(bytes, displayName, kMaxMeshInputBytes);
    if (plain.empty())
        throw MeshLoadError(displayName, "the file is empty after gzip decompression");
    return readUsableFormat(format, plain, displayName, baseDir);
}

} // namespace

std::string readMeshInputFile(const std::filesystem::path& path, const std::string& displayName)
{
    // Only regular files, checked before anything is opened: a FIFO would block and a
    // device like /dev/zero would never end (core/io/file_bytes.h).
    const std::string problem = io::regularFileProblem(path);
    if (problem == std::strerror(ENOENT))
        throw MeshLoadError(displayName, "cannot open the file: it does not exist");
    if (!problem.empty())
        throw MeshLoadError(displayName, "cannot open the file: it " + problem);
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (!error && size > kMaxMeshInputBytes)
        throw MeshLoadError(displayName, "the file has " + std::to_string(size) +
                                             " bytes, more than the 2 GiB a mesh file may have");
    try {
        return io::readFileBytes(path, kMaxMeshInputBytes);
    } catch (const std::runtime_error& e) {
        throw MeshLoadError(displayName, e.what());
    }
}

TriangleMesh loadMesh(const std::filesystem::path& path)
{
    const std::string displayName = path.string();
    const FormatRequest request = requestForPath(path);
    requireFormat(request, displayName); // reject unknown extensions before reading anything
    const std::string bytes = readMeshInputFile(path, displayName);
    std::filesystem::path baseDir = path.parent_path();
    if (baseDir.empty())
        baseDir = ".";
    return loadBytes(bytes, request, displayName, baseDir);
}

TriangleMesh loadMeshFromMemory(std::string_view bytes, std::string_view extension, const std::string& displayName)
{
    if (bytes.size() > kMaxMeshInputBytes)
        throw MeshLoadError(displayName, "the data has more than the 2 GiB a mesh may have");
    return loadBytes(bytes, parseExtension(extension), displayName, {});
}

std::vector<std::string> supportedMeshExtensions()
{
    std::vector<std::string> extensions(kExtensions.begin(), kExtensions.end());
    for (const std::string_view e : kExtensions)
        extensions.push_back(std::string(e) + ".gz");
    return extensions;
}

} // namespace trimlab
