// Fuzz target: skeleton files through parseSkeletonJson (skeleton/skeleton_json.h). The
// expected outcome for bad data is SkeletonFileError; a document that parses is written
// back with skeletonJson and must parse again to the same rig.
#include "fuzz_support.h"

#include "core/skeleton/skeleton_json.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using trimlab::SkeletonFileError;
    trimlab::fuzz::expectTypedErrors<SkeletonFileError>([&] {
        const auto document = trimlab::parseSkeletonJson(trimlab::fuzz::bytesOf(data, size), "fuzz.json");
        const std::string again = trimlab::skeletonJson(document.rig, document.curve ? &*document.curve : nullptr);
        try {
            const auto reread = trimlab::parseSkeletonJson(again, "fuzz-again.json");
            if (reread.rig.joints != document.rig.joints || reread.rig.parent != document.rig.parent) {
                std::fprintf(stderr, "FINDING: a parsed skeleton reads back different\n");
                std::abort();
            }
        } catch (const SkeletonFileError& error) {
            std::fprintf(stderr, "FINDING: a parsed skeleton does not read back: %s\n", error.what());
            std::abort();
        }
    });
    return 0;
}
