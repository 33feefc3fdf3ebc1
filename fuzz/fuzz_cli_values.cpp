// Fuzz target: the value parsers behind command-line options: --camera (parseCamera),
// --clip (parseClipPlane) and rule names. They report bad text as nullopt plus an error
// text and must never throw.
#include "fuzz_support.h"

#include "core/trim/clip_plane.h"
#include "core/trim/dynamic_rule.h"
#include "core/trim/static_rule.h"
#include "core/view/camera.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view text = trimlab::fuzz::bytesOf(data, size);
    trimlab::fuzz::expectTypedErrors<>([&] {
        std::string error;
        (void)trimlab::parseCamera(text, &error);
        (void)trimlab::parseClipPlane(text, &error);
        (void)trimlab::parseStaticRule(text);
        (void)trimlab::parseDynamicRule(text);
    });
    return 0;
}
