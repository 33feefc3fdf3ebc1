// Fuzz target: the command line's output-path check (core/io/output_paths.h) that every
// verb runs before any work. The input is up to four paths separated by newlines (NUL
// bytes, "..", links, very long names and all), checked from a private working folder
// that holds a file, a folder and a link; the check returns an error or nothing and never
// throws, and it writes nothing.
#include "fuzz_support.h"

#include "core/io/output_paths.h"

#include <filesystem>
#include <vector>

namespace {

/// A private working folder with something to collide with, made once per process.
void enterScratchFolder()
{
    static bool entered = false;
    if (entered)
        return;
    entered = true;
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / ("trimlab-fuzz-output-paths-" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder / "sub");
    std::ofstream(folder / "file.png") << "x";
    std::error_code error;
    std::filesystem::create_symlink("sub", folder / "link", error);
    std::filesystem::current_path(folder);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    enterScratchFolder();
    const std::string_view text = trimlab::fuzz::bytesOf(data, size);
    std::vector<trimlab::timeline::OutputRequest> requests;
    const char* options[] = {"-o", "--depth", "--ids", "--json"};
    std::size_t begin = 0;
    for (std::size_t i = 0; i < 4 && begin <= text.size(); ++i) {
        const std::size_t end = std::min(text.find('\n', begin), text.size());
        requests.push_back({options[i], std::string(text.substr(begin, end - begin))});
        begin = end + 1;
    }
    trimlab::fuzz::expectTypedErrors<>([&] { (void)trimlab::timeline::checkOutputPaths(requests); });
    return 0;
}
