#pragma once
/// \file
/// Where tests find their inputs and put their artifacts.

#include <filesystem>
#include <string>

namespace trimlab::test {

/// `tests/data/<relative>` in the source tree (small meshes, broken files), or under
/// $TRIMLAB_TEST_DATA_DIR when set (a test binary carried to another machine, e.g. by
/// scripts/gpu-check, whose source tree lies elsewhere).
[[nodiscard]] std::filesystem::path testDataPath(const std::string& relative);
/// `../shared/data/<relative>` (real third-party meshes, read in place), or under
/// $TRIMLAB_SHARED_DATA_DIR when set (as above).
[[nodiscard]] std::filesystem::path sharedDataPath(const std::string& relative);
/// A per-test output folder for failure artifacts (created on demand). CTest sets
/// TRIMLAB_TEST_OUTPUT_DIR; run by hand, the folder is ./test-output.
[[nodiscard]] std::filesystem::path outputDir();

} // namespace trimlab::test
