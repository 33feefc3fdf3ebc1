#include "core/mesh/gltf_document.h"

#include "core/io/file_bytes.h"
#include "core/io/json_nesting.h"

#include "core/mesh/byte_cursor.h"
#include "core/mesh/mesh_load_error.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <climits>

namespace trimlab {

namespace {

// tinygltf callbacks: never decode images, read external files only where allowed.

bool ignoreImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*)
{
    return true; // textures are irrelevant to geometry
}

/// Where external files may come from: nowhere for a document read from memory, else only
/// from inside the asset's own folder.
struct FileAccess {
    bool allowed = false;
    std::string base;             ///< the folder as handed to tinygltf (it joins URIs to it)
    std::filesystem::path folder; ///< the same folder, canonical
};

bool isImagePath(const std::string& path)
{
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    static const std::array<std::string_view, 9> images = {".png",   ".jpg", ".jpeg", ".ktx2", ".webp",
                                                           ".basis", ".dds", ".bmp",  ".gif"};
    return std::find(images.begin(), images.end(), ext) != images.end();
}

/// The URI as the file named it: tinygltf hands the callbacks `base + "/" + uri`.
std::string uriOf(const std::string& path, const FileAccess& access)
{
    const std::string prefix = access.base + "/";
    return path.starts_with(prefix) ? path.substr(prefix.size()) : path;
}

/// Why the external file at `path` may not be read, or "" when it may: a URI with a scheme
/// (http:, file:, ...), an absolute path, or a path that leaves the asset's folder once
/// "..", "." and symbolic links are resolved.
std::string containmentProblem(const std::string& path, const FileAccess& access)
{
    const std::string uri = uriOf(path, access);
    if (const std::size_t colon = uri.find(':');
        colon != std::string::npos && colon > 1 && uri.find_first_of("/\\") > colon)
        return "it names the URI scheme '" + uri.substr(0, colon) + ":'; only files inside the asset's folder are read";
    if (uri.starts_with('/') || uri.starts_with('\\'))
        return "it is an absolute path; only files inside the asset's folder are read";
    std::error_code error;
    const std::filesystem::path resolved = std::filesystem::weakly_canonical(path, error);
    if (error)
        return "it cannot be resolved (" + error.message() + ")";
    const std::filesystem::path relative = resolved.lexically_relative(access.folder);
    if (relative.empty() || *relative.begin() == "..")
        return "it resolves to " + resolved.string() + ", outside the asset's folder " + access.folder.string();
    return {};
}

bool fileExists(const std::string& path, void* user)
{
    const FileAccess& access = *static_cast<FileAccess*>(user);
    if (!access.allowed || !containmentProblem(path, access).empty())
        return true; // let readWholeFile refuse it with a clear message
    return !isImagePath(path) && io::regularFileProblem(path).empty();
}

std::string expandFilePath(const std::string& path, void*)
{
    return path;
}

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user)
{
    if (isImagePath(path))
        return false; // textures are never read (tinygltf treats this as a warning)
    const FileAccess& access = *static_cast<FileAccess*>(user);
    const std::string uri = uriOf(path, access);
    if (!access.allowed) {
        if (err)
            *err += "external file '" + uri + "' cannot be read when loading from memory\n";
        return false;
    }
    if (const std::string problem = containmentProblem(path, access); !problem.empty()) {
        if (err)
            *err += "external file '" + uri + "' is refused: " + problem + "\n";
        return false;
    }
    try {
        const std::string bytes = io::readFileBytes(path, std::size_t(2) << 30);
        out->assign(bytes.begin(), bytes.end());
    } catch (const std::runtime_error& e) {
        if (err)
            *err += "external file '" + uri + "': " + e.what() + "\n";
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

// GLB framing (glTF 2.0 §4.4): after the 12-byte header, chunks of an 8-byte header (length,
// type) and their data follow one another up to the declared length; the first is JSON.
// A chunk that runs past the declared length is refused before any chunk is read.
void checkGlbChunks(std::string_view file, const std::string& name)
{
    constexpr std::uint32_t kJson = 0x4E4F534A;
    std::size_t offset = 12;
    for (int chunk = 0; offset < file.size(); ++chunk) {
        const std::string which = "chunk " + std::to_string(chunk) + " at byte " + std::to_string(offset);
        if (file.size() - offset < 8)
            throw MeshLoadError(name, "binary glTF " + which + ": its 8-byte header runs past the " +
                                          std::to_string(file.size()) + " bytes the file declares");
        const auto length = decodeScalar<std::uint32_t>(file.data() + offset, std::endian::little);
        const auto type = decodeScalar<std::uint32_t>(file.data() + offset + 4, std::endian::little);
        if (chunk == 0 && type != kJson)
            throw MeshLoadError(name, "binary glTF: the first chunk must be JSON");
        if (length > file.size() - offset - 8)
            throw MeshLoadError(name, "binary glTF " + which + " declares " + std::to_string(length) +
                                          " bytes, but only " + std::to_string(file.size() - offset - 8) +
                                          " follow in the file");
        offset += 8 + std::size_t(length);
    }
    if (offset == 12)
        throw MeshLoadError(name, "binary glTF: no JSON chunk follows the header");
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
    checkGlbChunks(bytes.substr(0, length), name);
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

/// A vertex attribute's name (its value is an accessor index).
bool isAttributeSemantic(std::string_view key)
{
    static constexpr std::array<std::string_view, 7> kSemantics = {"POSITION", "NORMAL",  "TANGENT", "TEXCOORD_",
                                                                   "COLOR_",   "JOINTS_", "WEIGHTS_"};
    return std::any_of(kSemantics.begin(), kSemantics.end(),
                       [&](std::string_view semantic) { return key.starts_with(semantic); });
}

/// glTF's indices, counts and offsets are never negative, but tinygltf reads a negative
/// `byteOffset` as absent (0) and a negative `bufferView` as "no view" (zeros): a file that
/// says -4 would load as if it said nothing. This finds the first key among them (and the
/// attribute semantics, POSITION ...) whose value is a negative number, and
/// returns "KEY": VALUE, or "" when there is none. Strings are skipped with their escapes.
std::string firstNegativeIndex(std::string_view json)
{
    static constexpr std::array<std::string_view, 19> kKeys = {
        "byteOffset", "byteLength", "byteStride", "count",    "bufferView", "buffer",  "scene",
        "mesh",       "skin",       "camera",     "material", "source",     "sampler", "input",
        "output",     "indices",    "node",       "texCoord", "skeleton"};
    std::string_view key;
    for (std::size_t i = 0; i < json.size(); ++i) {
        if (json[i] == '"') {
            const std::size_t begin = ++i;
            while (i < json.size() && json[i] != '"')
                i += json[i] == '\\' ? 2 : 1;
            key = json.substr(begin, std::min(i, json.size()) - begin);
            continue;
        }
        if (json[i] != ':')
            continue;
        std::size_t v = i + 1;
        while (v < json.size() && std::isspace(static_cast<unsigned char>(json[v])))
            ++v;
        const bool indexKey = std::find(kKeys.begin(), kKeys.end(), key) != kKeys.end() || isAttributeSemantic(key);
        if (indexKey && v < json.size() && json[v] == '-') {
            std::size_t end = v + 1;
            while (end < json.size() && (std::isdigit(static_cast<unsigned char>(json[end])) || json[end] == '.'))
                ++end;
            return "\"" + std::string(key) + "\": " + std::string(json.substr(v, end - v));
        }
    }
    return {};
}

// tinygltf quotes a data URI whole in its messages; a file's embedded buffer may be
// hundreds of megabytes of base64. The first 16 characters say which one it was.
std::string shortenDataUris(std::string text)
{
    constexpr std::string_view kMarker = ";base64,";
    constexpr std::size_t kKept = 16;
    for (std::size_t at = text.find(kMarker); at != std::string::npos; at = text.find(kMarker, at + 1)) {
        const std::size_t begin = at + kMarker.size();
        std::size_t end = begin;
        while (end < text.size() &&
               (std::isalnum(std::uint8_t(text[end])) || text[end] == '+' || text[end] == '/' || text[end] == '='))
            ++end;
        if (end - begin > kKept)
            text.replace(begin + kKept, end - begin - kKept,
                         "\u2026 (" + std::to_string(end - begin - kKept) + " more characters)");
    }
    return text;
}

std::string cleanMessage(std::string text)
{
    while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
        text.pop_back();
    std::replace(text.begin(), text.end(), '\n', ';');
    return shortenDataUris(std::move(text));
}

tinygltf::Model parseModel(std::string_view bytes, const std::string& name, const std::filesystem::path& baseDir)
{
    if (bytes.size() > UINT_MAX)
        throw MeshLoadError(name, "the glTF data is larger than 4 GiB, which tinygltf cannot read");
    const bool binary = hasGlbMagic(bytes);
    if (binary)
        checkGlbHeader(bytes, name);
    else if (bytes.find_first_not_of(" \t\r\n") == std::string_view::npos ||
             bytes[bytes.find_first_not_of(" \t\r\n")] != '{')
        throw MeshLoadError(name,
                            "not a glTF file: neither JSON (starting with '{') nor binary glTF (starting with 'glTF')");
    if (io::jsonTooDeepAt(jsonPart(bytes, binary), kMaxJsonNesting) != std::string_view::npos)
        throw MeshLoadError(name, "invalid glTF: the JSON is nested more than " + std::to_string(kMaxJsonNesting) +
                                      " levels deep");
    if (const std::string negative = firstNegativeIndex(jsonPart(bytes, binary)); !negative.empty())
        throw MeshLoadError(name, "invalid glTF: " + negative +
                                      " is negative; indices, counts and offsets in glTF are never negative");
    FileAccess access;
    if (!baseDir.empty()) {
        std::error_code error;
        access = {true, baseDir.string(), std::filesystem::weakly_canonical(baseDir, error)};
        if (error)
            throw MeshLoadError(name, "cannot resolve the asset's folder " + baseDir.string() + ": " + error.message());
    }
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
            ok = loader.LoadBinaryFromMemory(
                &model, &error, &warning, reinterpret_cast<const unsigned char*>(bytes.data()), size, baseDir.string());
        else
            ok = loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(), size, baseDir.string());
    } catch (const std::exception& e) {
        throw MeshLoadError(name, std::string("invalid glTF: ") + e.what());
    }
    if (!ok)
        throw MeshLoadError(name, "invalid glTF: " + cleanMessage(error.empty() ? warning : error));
    return model;
}

// glTF 2.0 §3.12: a file that lists an extension in extensionsRequired must not be loaded
// by a reader that does not implement it (its data may mean something else without it).
// extensionsUsed alone is only a hint and is ignored. TrimLab reads positions, indices,
// node transforms, skins and morph targets; of the registered extensions it implements only
// KHR_mesh_quantization (integer and normalized position accessors, gltf_accessor.cpp).
void checkRequiredExtensions(const tinygltf::Model& model, const std::string& name)
{
    for (const std::string& extension : model.extensionsRequired) {
        if (extension == "KHR_mesh_quantization")
            continue;
        const bool compression = extension == "KHR_draco_mesh_compression" || extension == "EXT_meshopt_compression" ||
                                 extension == "KHR_meshopt_compression";
        throw MeshLoadError(name, "the file requires the extension '" + extension +
                                      "', which TrimLab does not implement (glTF 2.0: such a file must not be "
                                      "loaded without it); " +
                                      (compression ? "re-export without mesh compression" : "re-export without it"));
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
