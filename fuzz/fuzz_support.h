#pragma once
/// \file
/// What every fuzz target shares: running a loader so that its documented, typed load
/// errors count as a normal outcome and anything else (another exception type) aborts
/// with a message libFuzzer records as a crash; and per-process temporary files for the
/// loaders that only read paths. Crashes, sanitizer reports, out-of-memory and
/// timeouts are detected by libFuzzer itself.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <typeinfo>

#include <unistd.h>

namespace trimlab::fuzz {

/// The fuzz input as a string view.
inline std::string_view bytesOf(const std::uint8_t* data, std::size_t size)
{
    return {reinterpret_cast<const char*>(data), size};
}

/// Calls `load()`; returns normally when it succeeds or throws one of `Expected...`.
/// Any other exception is a finding: its type and message are printed and the process
/// aborts.
template <class... Expected, class Load>
void expectTypedErrors(Load&& load)
{
    try {
        try {
            load();
        } catch (const std::exception& error) {
            if ((... || (dynamic_cast<const Expected*>(&error) != nullptr)))
                return;
            throw;
        }
    } catch (const std::exception& error) {
        std::fprintf(stderr, "FINDING: unexpected exception %s: %s\n", typeid(error).name(), error.what());
        std::abort();
    } catch (...) {
        std::fprintf(stderr, "FINDING: unexpected non-std exception\n");
        std::abort();
    }
}

/// A folder of this process's own under the system temporary folder (created once,
/// removed at exit), so parallel fuzzers (-jobs, -workers) never share files.
inline const std::filesystem::path& scratchFolder()
{
    static const std::filesystem::path folder = [] {
        std::filesystem::path f =
            std::filesystem::temp_directory_path() / ("trimlab-fuzz-" + std::to_string(::getpid()));
        std::filesystem::create_directories(f);
        std::atexit([] {
            std::error_code ignored;
            std::filesystem::remove_all(scratchFolder(), ignored);
        });
        return f;
    }();
    return folder;
}

/// Writes `bytes` to scratchFolder()/name, replacing what was there; returns the path.
inline std::filesystem::path writeScratchFile(const std::string& name, std::string_view bytes)
{
    const std::filesystem::path path = scratchFolder() / name;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    return path;
}

} // namespace trimlab::fuzz
