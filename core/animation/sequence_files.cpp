#include "core/animation/sequence_files.h"

#include "core/animation/natural_order.h"
#include "core/mesh/mesh_load_error.h"

#include <algorithm>
#include <cctype>
#include <functional>
#include <optional>
#include <set>

namespace trimlab {

namespace {

namespace fs = std::filesystem;

std::string toLower(std::string text)
{
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return text;
}

// "obj" for "mesh.obj.gz", "" when the name has no extension.
std::string meshExtension(const std::string& fileName)
{
    std::string name = toLower(fileName);
    if (name.size() > 3 && name.ends_with(".gz"))
        name.resize(name.size() - 3);
    const std::size_t dot = name.rfind('.');
    return dot == std::string::npos ? std::string() : name.substr(dot + 1);
}

bool isSequenceExtension(const std::string& extension)
{
    return extension == "obj" || extension == "ply" || extension == "off" || extension == "stl";
}

// A file name pattern: literal text with '*' / '?' wildcards, or with one run of digits.
struct NamePattern {
    std::string prefix;        // for numbered patterns
    std::string suffix;        // for numbered patterns
    std::size_t minDigits = 1; // for numbered patterns
    std::optional<std::string> glob;
};

bool globMatch(std::string_view pattern, std::string_view name)
{
    std::size_t p = 0;
    std::size_t n = 0;
    std::size_t starP = std::string_view::npos;
    std::size_t starN = 0;
    while (n < name.size()) {
        if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == name[n])) {
            ++p;
            ++n;
        } else if (p < pattern.size() && pattern[p] == '*') {
            starP = p++;
            starN = n;
        } else if (starP != std::string_view::npos) {
            p = starP + 1;
            n = ++starN;
        } else {
            return false;
        }
    }
    while (p < pattern.size() && pattern[p] == '*')
        ++p;
    return p == pattern.size();
}

bool numberedMatch(const NamePattern& pattern, const std::string& name)
{
    if (name.size() < pattern.prefix.size() + pattern.suffix.size() + pattern.minDigits)
        return false;
    if (!name.starts_with(pattern.prefix) || !name.ends_with(pattern.suffix))
        return false;
    const std::string_view digits = std::string_view(name).substr(
        pattern.prefix.size(), name.size() - pattern.prefix.size() - pattern.suffix.size());
    return digits.size() >= pattern.minDigits &&
           std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// Parses "%d", "%0Nd" and "%%" in `text`; nullopt when there is no conversion.
std::optional<NamePattern> parseNumbered(const std::string& text, const std::string& spec)
{
    NamePattern pattern;
    bool found = false;
    std::string* out = &pattern.prefix;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '%') {
            *out += text[i];
            continue;
        }
        if (i + 1 < text.size() && text[i + 1] == '%') {
            *out += '%';
            ++i;
            continue;
        }
        std::size_t j = i + 1;
        while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j])))
            ++j;
        if (j >= text.size() || text[j] != 'd' || found)
            throw MeshLoadError(spec, "malformed numbered pattern: use one %d or %0Nd (e.g. mesh_%04d.obj)");
        const std::string width = text.substr(i + 1, j - i - 1);
        pattern.minDigits = width.empty() ? 1 : std::max<std::size_t>(1, std::stoul(width.substr(0, 6)));
        found = true;
        out = &pattern.suffix;
        i = j;
    }
    if (!found)
        return std::nullopt;
    return pattern;
}

std::vector<fs::path> listMatching(const fs::path& folder, const std::string& spec,
                                   const std::function<bool(const std::string&)>& accept)
{
    std::error_code error;
    if (!fs::is_directory(folder, error))
        throw MeshLoadError(spec, "the folder '" + folder.string() + "' does not exist");
    std::vector<fs::path> files;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder, error)) {
        std::error_code typeError;
        if (entry.is_regular_file(typeError) && accept(entry.path().filename().string()))
            files.push_back(entry.path());
    }
    if (error)
        throw MeshLoadError(spec, "cannot list the folder '" + folder.string() + "': " + error.message());
    std::sort(files.begin(), files.end(), [](const fs::path& a, const fs::path& b) {
        return naturalLess(a.filename().string(), b.filename().string());
    });
    return files;
}

void requireOneFormat(const std::vector<fs::path>& files, const std::string& spec)
{
    std::set<std::string> extensions;
    for (const fs::path& file : files)
        extensions.insert(meshExtension(file.filename().string()));
    if (extensions.size() > 1)
        throw MeshLoadError(spec, "the folder holds ." + *extensions.begin() + " and ." +
                                      *std::next(extensions.begin()) +
                                      " files; name a pattern (e.g. dir/mesh_*.obj) to choose one sequence");
}

std::vector<fs::path> folderFiles(const fs::path& folder, const std::string& spec)
{
    std::vector<fs::path> files =
        listMatching(folder, spec, [](const std::string& name) { return isSequenceExtension(meshExtension(name)); });
    if (files.empty())
        throw MeshLoadError(spec, "the folder holds no .obj, .ply, .off or .stl files (optionally .gz)");
    requireOneFormat(files, spec);
    return files;
}

std::vector<fs::path> patternFiles(const fs::path& path, const std::string& spec)
{
    const std::string name = path.filename().string();
    const fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
    std::vector<fs::path> files;
    if (const std::optional<NamePattern> numbered = parseNumbered(name, spec))
        files = listMatching(folder, spec, [&](const std::string& n) { return numberedMatch(*numbered, n); });
    else
        files = listMatching(folder, spec, [&](const std::string& n) { return globMatch(name, n); });
    if (files.empty())
        throw MeshLoadError(spec, "no file in '" + folder.string() + "' matches the pattern '" + name + "'");
    return files;
}

} // namespace

std::vector<fs::path> sequenceFiles(const std::string& spec)
{
    const fs::path path(spec);
    std::error_code error;
    if (fs::is_directory(path, error))
        return folderFiles(path, spec);
    const std::string folderText = path.parent_path().string();
    if (folderText.find_first_of("*?%") != std::string::npos && !fs::exists(path.parent_path(), error))
        throw MeshLoadError(spec, "wildcards and %d are supported only in the file name, not in the folder part");
    if (path.filename().string().find_first_of("*?%") != std::string::npos)
        return patternFiles(path, spec);
    if (fs::is_regular_file(path, error))
        throw MeshLoadError(spec, "a single mesh file is not an animation; name a folder, a pattern such as "
                                  "mesh_%04d.obj or mesh_*.obj, or a glTF file");
    throw MeshLoadError(spec, "no such folder or file");
}

bool isMeshSequenceSource(const std::string& source)
{
    std::error_code error;
    return fs::is_directory(fs::path(source), error) ||
           fs::path(source).filename().string().find_first_of("*?%") != std::string::npos;
}

bool isGltfSource(const std::string& source)
{
    const std::string extension = meshExtension(fs::path(source).filename().string());
    return extension == "gltf" || extension == "glb";
}

} // namespace trimlab
