// Fuzz target: .trimlab project documents through parseProject (project_file.h). The
// expected outcome for bad data is ProjectFileError; a document that parses is written
// back with projectJson and must parse again (round trip).
#include "fuzz_support.h"

#include "core/timeline/project_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using trimlab::timeline::ProjectFileError;
    trimlab::fuzz::expectTypedErrors<ProjectFileError>([&] {
        const auto project = trimlab::timeline::parseProject(trimlab::fuzz::bytesOf(data, size), "fuzz.trimlab");
        const std::string again = trimlab::timeline::projectJson(project.timeline, project.extras);
        try {
            (void)trimlab::timeline::parseProject(again, "fuzz-again.trimlab");
        } catch (const ProjectFileError& error) {
            std::fprintf(stderr, "FINDING: a parsed project does not read back: %s\n", error.what());
            std::abort();
        }
    });
    return 0;
}
