// Fuzz target: the command line's output-path check (core/io/output_paths.h) that every
// verb runs before any work. The input is up to four paths separated by newlines (NUL
// bytes, "..", links, very long names and all); relative ones are taken inside a private
// scratch folder that holds a file, a folder and a link (the working folder is not
// changed: libFuzzer reads its corpus by relative paths). The check returns an error or
// nothing and never throws, and it writes nothing.
#include "fuzz_support.h"

#include "core/io/output_paths.h"

#include <filesystem>
#include <vector>

namespace {

/// A private scratch folder with something to collide with, made once per process.
const std::string& scratchFolder()
{
    static const std::string folder = [] {
        const std::filesystem::path path =
            std::filesystem::temp_directory_path() / ("trimlab-fuzz-output-paths-" + std::to_string(::getpid()));
        std::filesystem::create_directories(path / "sub");
        std::ofstream(path / "file.png") << "x";
        std::error_code error;
        std::filesystem::create_symlink("sub", path / "link", error);
        return path.string() + "/";
    }();
    return folder;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view text = trimlab::fuzz::bytesOf(data, size);
    std::vector<trimlab::io::OutputRequest> requests;
    const char* options[] = {"-o", "--depth", "--ids", "--json"};
    std::size_t begin = 0;
    for (std::size_t i = 0; i < 4 && begin <= text.size(); ++i) {
        const std::size_t end = std::min(text.find('\n', begin), text.size());
        const std::string_view path = text.substr(begin, end - begin);
        requests.push_back(
            {options[i], path.starts_with('/') ? std::string(path) : scratchFolder() + std::string(path)});
        begin = end + 1;
    }
    trimlab::fuzz::expectTypedErrors<>([&] { (void)trimlab::io::checkOutputPaths(requests); });
    return 0;
}
