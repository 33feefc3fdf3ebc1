#include "core/io/stale_temporaries.h"

#include <algorithm>
#include <string>
#include <system_error>

namespace trimlab::io {

namespace {

constexpr std::string_view kTemporaryMarker = ".tmp-";
constexpr std::size_t kSuffixLength = 6;

bool isSuffixCharacter(char c)
{
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9');
}

bool olderThan(const std::filesystem::path& file, std::chrono::seconds minimumAge)
{
    std::error_code error;
    const auto modified = std::filesystem::last_write_time(file, error);
    if (error)
        return false;
    return std::filesystem::file_time_type::clock::now() - modified >= minimumAge;
}

} // namespace

bool isAtomicWriteTemporaryOf(const std::filesystem::path& target, const std::filesystem::path& candidate)
{
    const std::string prefix = target.filename().string() + std::string(kTemporaryMarker);
    const std::string name = candidate.filename().string();
    if (name.size() != prefix.size() + kSuffixLength || name.compare(0, prefix.size(), prefix) != 0)
        return false;
    return std::all_of(name.begin() + std::ptrdiff_t(prefix.size()), name.end(), isSuffixCharacter);
}

std::vector<std::filesystem::path> removeStaleTemporaries(const std::filesystem::path& target,
                                                          std::chrono::seconds minimumAge)
{
    std::vector<std::filesystem::path> removed;
    const std::filesystem::path folder = target.parent_path().empty() ? "." : target.parent_path();
    std::error_code error;
    std::filesystem::directory_iterator entries(folder, error);
    if (error)
        return removed;
    for (const std::filesystem::directory_entry& entry : entries) {
        std::error_code entryError;
        if (!entry.is_regular_file(entryError) || !isAtomicWriteTemporaryOf(target, entry.path()))
            continue;
        if (!olderThan(entry.path(), minimumAge))
            continue;
        if (std::filesystem::remove(entry.path(), entryError))
            removed.push_back(entry.path());
    }
    return removed;
}

} // namespace trimlab::io
