#include "core/io/atomic_write.h"

#include "core/io/stale_temporaries.h"

#include <cerrno>
#include <cstring>
#include <random>
#include <stdexcept>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

namespace trimlab::io {

namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& step, int error)
{
    throw std::runtime_error("cannot write " + path.string() + ": " + step + ": " + std::strerror(error));
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

// Creates a fresh temporary file next to `path`; returns its descriptor and name.
int createTemporary(const std::filesystem::path& path, std::filesystem::path& temporary)
{
    for (int attempt = 0; attempt < 100; ++attempt) {
        temporary = path;
        temporary += ".tmp-" + randomSuffix();
        const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0)
            return fd;
        if (errno != EEXIST)
            fail(path, "create " + temporary.filename().string(), errno);
    }
    fail(path, "create a temporary file", EEXIST);
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

void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes)
{
    std::filesystem::path temporary;
    const int fd = createTemporary(path, temporary);
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
        fail(path, step, error);
    }
    syncFolder(path.parent_path());
    // Leftovers of earlier saves of this file that were killed before their rename.
    removeStaleTemporaries(path, kStaleTemporaryAge);
}

} // namespace trimlab::io
