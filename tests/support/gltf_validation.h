#pragma once
/// \file
/// Validating exported glTF files with the Khronos glTF Validator in tests.

#include <filesystem>

namespace trimlab::test {

/// Runs scripts/gltf-validator on `file` (installing the validator on first use) and
/// fails the calling test unless it reports zero errors. A missing Node.js or an
/// unreachable npm registry fails the test too: an export must be validated. Use with
/// QVERIFY(!QTest::currentTestFailed()) or at the end of a test function.
void requireValidGltf(const std::filesystem::path& file);

} // namespace trimlab::test
