// Fuzz target: OFF meshes through loadMeshFromMemory (mesh_io.h). Expected outcome for
// bad data: MeshLoadError.
#include "fuzz_support.h"

#include "core/mesh/mesh_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    trimlab::fuzz::expectTypedErrors<trimlab::MeshLoadError>(
        [&] { (void)trimlab::loadMeshFromMemory(trimlab::fuzz::bytesOf(data, size), "off", "fuzz.off"); });
    return 0;
}
