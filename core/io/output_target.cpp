#include "core/io/output_target.h"

#include <cerrno>
#include <system_error>

#include <sys/stat.h>
#include <unistd.h>

namespace trimlab::io {

namespace {

namespace fs = std::filesystem;

// The kernel's own bound on links followed in one lookup (MAXSYMLINKS).
constexpr int kMaxLinks = 40;

fs::path folderOf(const fs::path& path)
{
    const fs::path parent = path.parent_path();
    return parent.empty() ? fs::path(".") : parent;
}

} // namespace

std::optional<fs::path> followOutputLinks(const fs::path& path)
{
    fs::path current = path;
    for (int links = 0; links <= kMaxLinks; ++links) {
        std::error_code error;
        if (!fs::is_symlink(fs::symlink_status(current, error)))
            return current;
        const fs::path target = fs::read_symlink(current, error);
        if (error)
            return current;
        current = target.is_absolute() ? target : current.parent_path() / target;
    }
    return std::nullopt;
}

std::string nonRegularKind(const fs::path& file)
{
    struct stat status {};
    if (::lstat(file.c_str(), &status) != 0)
        return {};
    switch (status.st_mode & S_IFMT) {
    case S_IFREG:
        return {};
    case S_IFDIR:
        return "a folder";
    case S_IFIFO:
        return "a FIFO (named pipe)";
    case S_IFSOCK:
        return "a socket";
    case S_IFCHR:
        return "a character device";
    case S_IFBLK:
        return "a block device";
    case S_IFLNK:
        return "a symbolic link";
    default:
        return "not a regular file";
    }
}

std::size_t fileNameLimit(const fs::path& folder)
{
    errno = 0;
    const long limit = ::pathconf(folder.c_str(), _PC_NAME_MAX);
    return limit > 0 ? std::size_t(limit) : std::size_t(255);
}

OutputTarget resolveOutputTarget(const fs::path& path)
{
    const std::optional<fs::path> file = followOutputLinks(path);
    if (!file)
        return {path, path.string() + " is a loop of symbolic links (or a chain of more than 40); give a file name"};
    const std::string name = file->filename().string();
    if (name.empty() || name == "." || name == "..")
        return {*file, path.string() + " names a folder; give a file name"};
    if (const std::size_t limit = fileNameLimit(folderOf(*file)); name.size() > limit)
        return {*file, path.string() + ": the file name has " + std::to_string(name.size()) + " bytes, more than the " +
                           std::to_string(limit) + " its folder allows"};
    if (const std::string kind = nonRegularKind(*file); !kind.empty()) {
        const std::string shown = *file == path ? path.string() : path.string() + " (a link to " + file->string() + ")";
        return {*file,
                shown + " is " + kind + (kind == "a folder" ? "" : ", not a regular file") + "; give a file name"};
    }
    return {*file, {}};
}

} // namespace trimlab::io
