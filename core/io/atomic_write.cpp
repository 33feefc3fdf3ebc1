#include "core/io/atomic_write.h"

#include "core/io/output_target.h"
#include "core/io/stale_temporaries.h"

#include <cerrno>
#include <cstring>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace trimlab::io {

namespace {

// What a user can do about the errors a batch farm meets most.
std::string adviceFor(int error)
{
    switch (error) {
    case EFBIG:
        return " (the file-size limit of this process, ulimit -f, was reached)";
    case ENOSPC:
    case EDQUOT:
        return " (free some space or write elsewhere)";
    default:
        return {};
    }
}

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& step, int error, bool existed)
{
    throw std::runtime_error("cannot write " + path.string() + ": " + step + ": " + std::strerror(error) +
                             adviceFor(error) + (existed ? "; the existing file is unchanged" : ""));
}

// The mode of the regular file a save replaces, or nullopt for a new file.
std::optional<mode_t> existingMode(const std::filesystem::path& file)
{
    struct stat status {};
    if (::stat(file.c_str(), &status) != 0 || !S_ISREG(status.st_mode))
        return std::nullopt;
    return status.st_mode & 07777;
}

std::string randomSuffix()
{
    static constexpr char kChars[] = "abcdefghijklmnopqrstuvwxyz0123456789";
    std::random_device device;
    std::string suffix;
    for (int i = 0; i < 6; ++i)
        suffix += kChars[device() % (sizeof kChars - 1)];
    return suffix;
}

// Creates a fresh temporary file next to `path`; returns its descriptor and name. A new
// file gets 0666 less the umask (the kernel applies it); one that replaces a file starts
// private (0600) and takes the old file's mode before anything is written, so a private
// file's contents are never readable by others, not even for a moment.
int createTemporary(const std::filesystem::path& path, std::optional<mode_t> mode, std::filesystem::path& temporary)
{
    const std::filesystem::path folder = path.parent_path().empty() ? "." : path.parent_path();
    const std::string prefix = temporaryPrefix(path, fileNameLimit(folder));
    for (int attempt = 0; attempt < 100; ++attempt) {
        temporary = path.parent_path() / (prefix + randomSuffix());
        const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, mode ? 0600 : 0666);
        if (fd < 0 && errno == EEXIST)
            continue;
        if (fd < 0)
            fail(path, "create " + temporary.filename().string(), errno, mode.has_value());
        if (mode && ::fchmod(fd, *mode) != 0) {
            const int error = errno;
            ::close(fd);
            std::error_code ignored;
            std::filesystem::remove(temporary, ignored);
            fail(path, "keep the file's permissions", error, true);
        }
        return fd;
    }
    fail(path, "create a temporary file", EEXIST, mode.has_value());
}

// Writes everything and makes it durable; returns 0 or the errno of the failed step.
int writeAll(int fd, std::string_view bytes, std::string& step)
{
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0) {
            step = "write";
            return errno;
        }
        done += std::size_t(n);
    }
    if (::fsync(fd) != 0) {
        step = "fsync";
        return errno;
    }
    return 0;
}

void syncFolder(const std::filesystem::path& folder)
{
    // Makes the rename itself durable; some file systems refuse, which is harmless.
    const int fd = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
}

} // namespace

void writeFileAtomically(const std::filesystem::path& requested, std::string_view bytes)
{
    const OutputTarget target = resolveOutputTarget(requested);
    if (!target.problem.empty())
        throw std::runtime_error("cannot write " + target.problem);
    const std::filesystem::path& path = target.file;
    const std::optional<mode_t> mode = existingMode(path);
    std::filesystem::path temporary;
    const int fd = createTemporary(path, mode, temporary);
    std::string step;
    int error = writeAll(fd, bytes, step);
    if (::close(fd) != 0 && error == 0) {
        step = "close";
        error = errno;
    }
    if (error == 0) {
        std::error_code renameError;
        std::filesystem::rename(temporary, path, renameError);
        if (renameError) {
            step = "rename";
            error = renameError.value();
        }
    }
    if (error != 0) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        fail(path, step, error, mode.has_value());
    }
    syncFolder(path.parent_path());
    // Leftovers of earlier saves of this file that were killed before their rename.
    removeStaleTemporaries(path, kStaleTemporaryAge);
}

} // namespace trimlab::io
