// Fuzz target: NURBS surface files through parseNurbsJson (surface/nurbs_json.h). The
// expected outcome for bad data is NurbsFileError; a document that parses is written back
// with nurbsJson and must parse again to the same surfaces (doubles are written with
// round-trip precision, so bit-equal), and each surface must evaluate to finite points.
#include "fuzz_support.h"

#include "core/surface/nurbs_json.h"
#include "core/surface/nurbs_surface.h"

#include <cmath>

namespace {

void requireFiniteSamples(const trimlab::NurbsSurface& surface)
{
    // A 3×3 grid of parameters over the surface's domain, ends included (where knots and
    // poles are): a valid file must never give a NaN point or normal.
    const trimlab::ParameterRange ru = trimlab::parameterRangeU(surface);
    const trimlab::ParameterRange rv = trimlab::parameterRangeV(surface);
    for (int i = 0; i <= 2; ++i) {
        for (int j = 0; j <= 2; ++j) {
            const double u = ru.begin + ru.length() * i / 2.0;
            const double v = rv.begin + rv.length() * j / 2.0;
            const glm::dvec3 p = trimlab::evaluateNurbsPoint(surface, u, v);
            const glm::dvec3 n = trimlab::nurbsNormal(surface, u, v);
            for (int c = 0; c < 3; ++c) {
                if (!std::isfinite(p[c]) || !std::isfinite(n[c])) {
                    std::fprintf(stderr, "FINDING: a valid NURBS file evaluates to a non-finite point or normal\n");
                    std::abort();
                }
            }
        }
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using trimlab::NurbsFileError;
    trimlab::fuzz::expectTypedErrors<NurbsFileError>([&] {
        const auto surfaces = trimlab::parseNurbsJson(trimlab::fuzz::bytesOf(data, size), "fuzz.json");
        const std::string again = trimlab::nurbsJson(surfaces);
        try {
            if (trimlab::parseNurbsJson(again, "fuzz-again.json") != surfaces) {
                std::fprintf(stderr, "FINDING: parsed NURBS surfaces read back different\n");
                std::abort();
            }
        } catch (const NurbsFileError& error) {
            std::fprintf(stderr, "FINDING: parsed NURBS surfaces do not read back: %s\n", error.what());
            std::abort();
        }
        for (const auto& surface : surfaces)
            requireFiniteSamples(surface);
    });
    return 0;
}
