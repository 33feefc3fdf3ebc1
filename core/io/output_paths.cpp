#include "core/io/output_paths.h"

#include "core/io/output_target.h"

#include <cerrno>
#include <cstring>
#include <filesystem>

#include <unistd.h>

namespace trimlab::io {

namespace {

namespace fs = std::filesystem;

/// The folder a relative or absolute output path lands in.
fs::path folderOf(const fs::path& path)
{
    const fs::path parent = path.parent_path();
    return parent.empty() ? fs::path(".") : parent;
}

std::optional<std::string> checkOne(const OutputRequest& output)
{
    const std::string named = output.option + " " + output.path;
    if (output.path.find('\0') != std::string::npos)
        return named + ": a file name cannot hold a NUL byte";
    const OutputTarget target = resolveOutputTarget(fs::path(output.path));
    if (!target.problem.empty())
        return output.option + " " + target.problem;
    const fs::path& path = target.file;
    std::error_code error;
    const fs::path folder = folderOf(path);
    if (!fs::exists(folder, error))
        return error ? named + ": the folder " + folder.string() + " cannot be checked (" + error.message() + ")"
                     : named + ": the folder " + folder.string() + " does not exist";
    if (!fs::is_directory(folder, error))
        return named + ": " + folder.string() + " is not a folder";
    // The file is created beside its final name and renamed: the folder must be writable.
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        return named + ": cannot write into the folder " + folder.string() + " (" + std::strerror(errno) + ")";
    return std::nullopt;
}

/// The file `path` names, with its links and its folder resolved (the file itself need not
/// exist).
fs::path resolved(const std::string& path)
{
    const fs::path p = followOutputLinks(fs::path(path)).value_or(fs::path(path));
    std::error_code error;
    const fs::path absolute = fs::absolute(folderOf(p), error);
    const fs::path folder = fs::weakly_canonical(absolute, error);
    return (error ? absolute.lexically_normal() : folder) / p.filename();
}

} // namespace

std::optional<std::string> checkOutputPaths(const std::vector<OutputRequest>& outputs)
{
    for (const OutputRequest& output : outputs)
        if (!output.path.empty())
            if (auto e = checkOne(output))
                return e;
    for (std::size_t i = 0; i < outputs.size(); ++i)
        for (std::size_t j = i + 1; j < outputs.size(); ++j)
            if (!outputs[i].path.empty() && !outputs[j].path.empty() &&
                resolved(outputs[i].path) == resolved(outputs[j].path))
                return outputs[i].option + " and " + outputs[j].option + " both name " + outputs[j].path +
                       "; give each output its own file";
    return std::nullopt;
}

} // namespace trimlab::io
