// Fuzz target: subdivision cages through readCageObj (surface/cage_obj.h), then, for a
// cage that reads, one level of subdivision in limit mode (OpenSubdiv's refiner, patch
// and stencil tables see whatever topology the reader let through). The first byte picks
// the scheme (odd: Loop). Expected outcomes for bad data: MeshLoadError from the reader,
// SubdivisionError from the surface (a topology OpenSubdiv or our checks refuse).
#include "fuzz_support.h"

#include "core/mesh/mesh_load_error.h"
#include "core/surface/cage_obj.h"
#include "core/surface/subdivision_surface.h"

#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    if (size == 0)
        return 0;
    const auto scheme =
        (data[0] & 1u) != 0 ? trimlab::SubdivisionScheme::Loop : trimlab::SubdivisionScheme::CatmullClark;
    trimlab::fuzz::expectTypedErrors<trimlab::MeshLoadError, trimlab::SubdivisionError>([&] {
        const trimlab::SubdivisionCage cage =
            trimlab::readCageObj(trimlab::fuzz::bytesOf(data + 1, size - 1), "fuzz.obj", scheme);
        if (cage.faceCount() > 256)
            return; // the reader is what this target is for; big refinements only cost time
        const trimlab::SubdivisionSurface surface(cage, {1, trimlab::SubdivisionMode::Limit});
        for (const glm::vec3& p : surface.mesh().positions) {
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
                std::fprintf(stderr, "FINDING: a valid cage subdivides to a non-finite point\n");
                std::abort();
            }
        }
    });
    return 0;
}
