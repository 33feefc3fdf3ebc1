// Fuzz target: stroke scripts through parseStrokeScript (stroke_script.h). The expected
// outcome for bad data is StrokeScriptError; a script that parses is written back with
// strokeScriptJson and must parse again.
#include "fuzz_support.h"

#include "core/timeline/stroke_script.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using trimlab::timeline::StrokeScriptError;
    trimlab::fuzz::expectTypedErrors<StrokeScriptError>([&] {
        const auto script = trimlab::timeline::parseStrokeScript(trimlab::fuzz::bytesOf(data, size), "fuzz.json");
        if (script.sets.empty())
            return;
        const std::string again = trimlab::timeline::strokeScriptJson(script);
        try {
            (void)trimlab::timeline::parseStrokeScript(again, "fuzz-again.json");
        } catch (const StrokeScriptError& error) {
            std::fprintf(stderr, "FINDING: a parsed script does not read back: %s\n", error.what());
            std::abort();
        }
    });
    return 0;
}
