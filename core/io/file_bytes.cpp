#include "core/io/file_bytes.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <system_error>

namespace trimlab::timeline {

std::string readFileBytes(const std::filesystem::path& path, std::size_t maxBytes)
{
    std::error_code error;
    const auto status = std::filesystem::status(path, error);
    if (error)
        throw std::runtime_error("cannot open: " + error.message());
    if (!std::filesystem::is_regular_file(status))
        throw std::runtime_error("is not a regular file");
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (error)
        throw std::runtime_error("cannot read the size: " + error.message());
    if (size > maxBytes)
        throw std::runtime_error("is larger than " + std::to_string(maxBytes) + " bytes");
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw std::runtime_error(std::string("cannot open: ") + std::strerror(errno));
    std::string bytes(static_cast<std::size_t>(size), '\0');
    in.read(bytes.data(), std::streamsize(bytes.size()));
    if (in.gcount() != std::streamsize(bytes.size()))
        throw std::runtime_error("read error: got " + std::to_string(in.gcount()) + " of " +
                                 std::to_string(bytes.size()) + " bytes");
    return bytes;
}

} // namespace trimlab::timeline
