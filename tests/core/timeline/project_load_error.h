#pragma once
// The error parsing a damaged project document throws, for the project file tests.
#include "core/timeline/project_file.h"

#include <string>

namespace trimlab::test {

/// The ProjectFileError parseProject(text, file) throws; one reading "<loaded without an
/// error>" when it loads, so that the test's comparison of the reason fails.
inline timeline::ProjectFileError projectLoadError(const std::string& text, const std::string& file)
{
    try {
        (void)timeline::parseProject(text, file);
    } catch (const timeline::ProjectFileError& error) {
        return error;
    }
    return timeline::ProjectFileError(file, "", "<loaded without an error>");
}

} // namespace trimlab::test
