#include "core/io/file_bytes.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace trimlab::io {

namespace {

/// What a stat mode is, for a file that is not regular.
std::string kindOf(mode_t mode)
{
    const char* kind = S_ISDIR(mode)                    ? "a folder"
                       : S_ISFIFO(mode)                 ? "a named pipe (FIFO)"
                       : S_ISCHR(mode) || S_ISBLK(mode) ? "a device"
                       : S_ISSOCK(mode)                 ? "a socket"
                                                        : nullptr;
    return kind ? "is " + std::string(kind) + ", not a regular file" : "is not a regular file";
}

std::string errnoReason(int error)
{
    switch (error) {
    case ELOOP:
        return "is a loop of symbolic links, not a regular file";
    case ENOTDIR:
        return "does not exist (a folder on its path is a file)";
    default:
        return std::strerror(error);
    }
}

/// Closes the descriptor on every path out.
struct Descriptor {
    int fd = -1;
    ~Descriptor()
    {
        if (fd >= 0)
            ::close(fd);
    }
};

} // namespace

std::string regularFileProblem(const std::filesystem::path& path)
{
    struct stat info {};
    if (::stat(path.c_str(), &info) != 0)
        return errnoReason(errno);
    return S_ISREG(info.st_mode) ? std::string() : kindOf(info.st_mode);
}

std::string readFileBytes(const std::filesystem::path& path, std::size_t maxBytes)
{
    // The first check names the problem without opening anything (opening a FIFO or a
    // device may have effects); the second, on the open descriptor, closes the gap in
    // which the file could have been swapped.
    if (const std::string problem = regularFileProblem(path); !problem.empty())
        throw std::runtime_error("cannot open: " + problem);
    Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY)};
    if (file.fd < 0)
        throw std::runtime_error("cannot open: " + errnoReason(errno));
    struct stat info {};
    if (::fstat(file.fd, &info) != 0)
        throw std::runtime_error(std::string("cannot read the size: ") + std::strerror(errno));
    if (!S_ISREG(info.st_mode))
        throw std::runtime_error("cannot open: " + kindOf(info.st_mode));
    if (std::uintmax_t(info.st_size) > maxBytes)
        throw std::runtime_error("is larger than " + std::to_string(maxBytes) + " bytes");
    std::string bytes(static_cast<std::size_t>(info.st_size), '\0');
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t got = ::read(file.fd, bytes.data() + done, bytes.size() - done);
        if (got < 0 && errno == EINTR)
            continue;
        if (got < 0)
            throw std::runtime_error(std::string("read error: ") + std::strerror(errno));
        if (got == 0)
            throw std::runtime_error("read error: got " + std::to_string(done) + " of " + std::to_string(bytes.size()) +
                                     " bytes (the file shrank while it was read)");
        done += std::size_t(got);
    }
    return bytes;
}

} // namespace trimlab::io
