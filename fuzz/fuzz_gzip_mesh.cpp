// Fuzz target: gzip-wrapped meshes. The input goes through gunzip (gzip_input.h) with a
// small output cap, then through loadMeshFromMemory as .obj.gz, .off.gz, .ply.gz,
// .stl.gz and .glb.gz/.gltf.gz, so the decompressed bytes reach every reader. Expected
// outcome for bad data: MeshLoadError.
#include "fuzz_support.h"

#include "core/mesh/gzip_input.h"
#include "core/mesh/mesh_io.h"

#include <array>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view bytes = trimlab::fuzz::bytesOf(data, size);
    // The cap itself (a zip bomb must stop at it, not exhaust memory).
    trimlab::fuzz::expectTypedErrors<trimlab::MeshLoadError>([&] { (void)trimlab::gunzip(bytes, "fuzz.gz", 1 << 16); });
    static constexpr std::array<const char*, 5> kExtensions = {"obj.gz", "off.gz", "ply.gz", "stl.gz", "gltf.gz"};
    for (const char* extension : kExtensions) {
        trimlab::fuzz::expectTypedErrors<trimlab::MeshLoadError>(
            [&] { (void)trimlab::loadMeshFromMemory(bytes, extension, std::string("fuzz.") + extension); });
    }
    return 0;
}
