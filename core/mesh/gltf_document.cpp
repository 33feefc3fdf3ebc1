#include "core/mesh/gltf_document.h"

#include "core/io/json_nesting.h"

#include "core/mesh/byte_cursor.h"
#include "core/mesh/mesh_load_error.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <climits>
#include <fstream>

namespace trimlab {

namespace {

// tinygltf callbacks: never decode images, read external files only where allowed.

bool ignoreImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*)
{
    return true; // textures are irrelevant to geometry
}

struct FileAccess {
    bool allowed = false;
};

bool isImagePath(const std::string& path)
{
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    static const std::array<std::string_view, 9> images = {".png", ".jpg", ".jpeg", ".ktx2", ".webp",
                                                           ".basis", ".dds", ".bmp", ".gif"};
    return std::find(images.begin(), images.end(), ext) != images.end();
}

bool fileExists(const std::string& path, void* user)
{
    if (!static_cast<FileAccess*>(user)->allowed)
        return true; // let readWholeFile refuse it with a clear message
    std::error_code error;
    return !isImagePath(path) && std::filesystem::is_regular_file(path, error);
}

std::string expandFilePath(const std::string& path, void*)
{
    return path;
}

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user)
{
    if (isImagePath(path))
        return false; // textures are never read (tinygltf treats this as a warning)
    if (!static_cast<FileAccess*>(user)->allowed) {
        if (err)
            *err += "external file '" + path + "' cannot be read when loading from memory\n";
        return false;
    }
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (error || !std::filesystem::is_regular_file(path, error) || size > (std::uintmax_t(2) << 30)) {
        if (err)
            *err += "external file '" + path + "' is not a regular file of at most 2 GiB\n";
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    if (in)
        out->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (!in && !in.eof()) {
        if (err)
            *err += "cannot read external file '" + path + "'\n";
        return false;
    }
    return true;
}

bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*)
{
    if (err)
        *err += "writing is disabled\n";
    return false;
}

// Real assets nest a few levels; the limit only guards the recursive JSON parsers.
constexpr std::size_t kMaxJsonNesting = 256;

bool hasGlbMagic(std::string_view bytes)
{
    return bytes.size() >= 4 && bytes.substr(0, 4) == "glTF";
}

void checkGlbHeader(std::string_view bytes, const std::string& name)
{
    if (bytes.size() < 12)
        throw MeshLoadError(name, "truncated binary glTF: " + std::to_string(bytes.size()) +
                                      " bytes, less than the 12-byte GLB header");
    const auto version = decodeScalar<std::uint32_t>(bytes.data() + 4, std::endian::little);
    const auto length = decodeScalar<std::uint32_t>(bytes.data() + 8, std::endian::little);
    if (version != 2)
        throw MeshLoadError(name, "binary glTF version " + std::to_string(version) + " is not supported (only 2)");
    if (length > bytes.size())
        throw MeshLoadError(name, "truncated binary glTF: the header declares " + std::to_string(length) +
                                      " bytes, but the file has only " + std::to_string(bytes.size()));
}

// The JSON text of a glTF asset: the whole input, or a GLB's first chunk (clamped).
std::string_view jsonPart(std::string_view bytes, bool binary)
{
    if (!binary)
        return bytes;
    if (bytes.size() < 20)
        return {};
    const auto length = decodeScalar<std::uint32_t>(bytes.data() + 12, std::endian::little);
    return bytes.substr(20, length);
}

std::string cleanMessage(std::string text)
{
    while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
        text.pop_back();
    std::replace(text.begin(), text.end(), '\n', ';');
    return text;
}

tinygltf::Model parseModel(std::string_view bytes, const std::string& name, const std::filesystem::path& baseDir)
{
    if (bytes.size() > UINT_MAX)
        throw MeshLoadError(name, "the glTF data is larger than 4 GiB, which tinygltf cannot read");
    const bool binary = hasGlbMagic(bytes);
    if (binary)
        checkGlbHeader(bytes, name);
    else if (bytes.find_first_not_of(" \t\r\n") == std::string_view::npos || bytes[bytes.find_first_not_of(" \t\r\n")] != '{')
        throw MeshLoadError(name, "not a glTF file: neither JSON (starting with '{') nor binary glTF (starting with 'glTF')");
    if (jsonTooDeepAt(jsonPart(bytes, binary), kMaxJsonNesting) != std::string_view::npos)
        throw MeshLoadError(name, "invalid glTF: the JSON is nested more than " + std::to_string(kMaxJsonNesting) +
                                      " levels deep");
    FileAccess access{!baseDir.empty()};
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&ignoreImage, nullptr);
    loader.SetFsCallbacks({&fileExists, &expandFilePath, &readWholeFile, &refuseWrite, &access});
    tinygltf::Model model;
    std::string error;
    std::string warning;
    bool ok = false;
    const auto size = static_cast<unsigned int>(bytes.size());
    try {
        if (binary)
            ok = loader.LoadBinaryFromMemory(&model, &error, &warning, reinterpret_cast<const unsigned char*>(bytes.data()),
                                             size, baseDir.string());
        else
            ok = loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(), size, baseDir.string());
    } catch (const std::exception& e) {
        throw MeshLoadError(name, std::string("invalid glTF: ") + e.what());
    }
    if (!ok)
        throw MeshLoadError(name, "invalid glTF: " + cleanMessage(error.empty() ? warning : error));
    return model;
}

void checkRequiredExtensions(const tinygltf::Model& model, const std::string& name)
{
    for (const std::string& extension : model.extensionsRequired) {
        if (extension == "KHR_draco_mesh_compression" || extension == "EXT_meshopt_compression" ||
            extension == "KHR_meshopt_compression")
            throw MeshLoadError(name, "the file requires the extension " + extension +
                                          ", which is not supported; re-export without mesh compression");
    }
}

} // namespace

tinygltf::Model parseGltfDocument(std::string_view bytes, const std::string& displayName,
                                  const std::filesystem::path& baseDir)
{
    tinygltf::Model model = parseModel(bytes, displayName, baseDir);
    checkRequiredExtensions(model, displayName);
    return model;
}

} // namespace trimlab
