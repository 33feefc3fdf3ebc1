#include "test_paths.h"

#include <cstdlib>

namespace trimlab::test {

namespace {

/// The folder named by `variable` when it is set and not empty, else the one compiled in.
std::filesystem::path folder(const char* variable, const char* builtIn)
{
    const char* fromEnvironment = std::getenv(variable);
    return fromEnvironment && *fromEnvironment ? std::filesystem::path(fromEnvironment)
                                               : std::filesystem::path(builtIn);
}

} // namespace

std::filesystem::path testDataPath(const std::string& relative)
{
    return folder("TRIMLAB_TEST_DATA_DIR", TRIMLAB_TEST_DATA_DIR) / relative;
}

std::filesystem::path sharedDataPath(const std::string& relative)
{
    return folder("TRIMLAB_SHARED_DATA_DIR", TRIMLAB_SHARED_DATA_DIR) / relative;
}

std::filesystem::path outputDir()
{
    const char* env = std::getenv("TRIMLAB_TEST_OUTPUT_DIR");
    std::filesystem::path dir = env && *env ? std::filesystem::path(env) : std::filesystem::path("test-output");
    std::filesystem::create_directories(dir);
    return dir;
}

} // namespace trimlab::test
