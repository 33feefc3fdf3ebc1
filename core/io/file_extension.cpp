#include "core/io/file_extension.h"

#include <algorithm>
#include <cctype>

namespace trimlab::io {

std::string lowercaseExtension(const std::filesystem::path& path)
{
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return extension;
}

} // namespace trimlab::io
