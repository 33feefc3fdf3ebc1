#include "test_paths.h"

#include <cstdlib>

namespace trimlab::test {

std::filesystem::path testDataPath(const std::string& relative)
{
    return std::filesystem::path(TRIMLAB_TEST_DATA_DIR) / relative;
}

std::filesystem::path sharedDataPath(const std::string& relative)
{
    return std::filesystem::path(TRIMLAB_SHARED_DATA_DIR) / relative;
}

std::filesystem::path outputDir()
{
    const char* env = std::getenv("TRIMLAB_TEST_OUTPUT_DIR");
    std::filesystem::path dir = env && *env ? std::filesystem::path(env) : std::filesystem::path("test-output");
    std::filesystem::create_directories(dir);
    return dir;
}

} // namespace trimlab::test
