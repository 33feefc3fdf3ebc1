#include "core/io/stale_temporaries.h"

#include "core/io/output_target.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <system_error>

namespace trimlab::io {

namespace {

constexpr std::string_view kTemporaryMarker = ".tmp-";
constexpr std::size_t kHashLength = 9; // "~" and 8 hex digits

std::uint32_t nameHash(std::string_view name)
{
    std::uint32_t hash = 2166136261u; // FNV-1a
    for (const char c : name) {
        hash ^= std::uint8_t(c);
        hash *= 16777619u;
    }
    return hash;
}

std::string hexDigits(std::uint32_t value)
{
    static constexpr char kDigits[] = "0123456789abcdef";
    std::string text(8, '0');
    for (int i = 7; i >= 0; --i, value >>= 4)
        text[std::size_t(i)] = kDigits[value & 0xf];
    return text;
}

// The longest prefix of `name` of at most `bytes` bytes that does not split a UTF-8
// character.
std::string_view cutAtCharacter(std::string_view name, std::size_t bytes)
{
    std::size_t end = std::min(bytes, name.size());
    while (end > 0 && end < name.size() && (std::uint8_t(name[end]) & 0xc0) == 0x80)
        --end;
    return name.substr(0, end);
}

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

std::string temporaryPrefix(const std::filesystem::path& target, std::size_t nameLimit)
{
    const std::string name = target.filename().string();
    const std::size_t fixed = kTemporaryMarker.size() + kTemporarySuffixLength;
    if (name.size() + fixed <= nameLimit)
        return name + std::string(kTemporaryMarker);
    const std::size_t room = nameLimit > fixed + kHashLength ? nameLimit - fixed - kHashLength : 0;
    return std::string(cutAtCharacter(name, room)) + "~" + hexDigits(nameHash(name)) + std::string(kTemporaryMarker);
}

bool isAtomicWriteTemporaryOf(const std::filesystem::path& target, const std::filesystem::path& candidate)
{
    const std::filesystem::path folder = target.parent_path().empty() ? "." : target.parent_path();
    const std::string prefix = temporaryPrefix(target, fileNameLimit(folder));
    const std::string name = candidate.filename().string();
    if (name.size() != prefix.size() + kTemporarySuffixLength || name.compare(0, prefix.size(), prefix) != 0)
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
