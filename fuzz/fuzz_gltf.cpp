// Fuzz target: glTF 2.0 meshes, both forms, through loadMeshFromMemory (mesh_io.h). Data
// that starts with the GLB magic "glTF" is read as .glb, everything else as .gltf JSON
// (embedded buffers only: there is no folder for external ones). Expected outcome for
// bad data: MeshLoadError.
#include "fuzz_support.h"

#include "core/mesh/mesh_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view bytes = trimlab::fuzz::bytesOf(data, size);
    const bool binary = bytes.substr(0, 4) == "glTF";
    trimlab::fuzz::expectTypedErrors<trimlab::MeshLoadError>(
        [&] { (void)trimlab::loadMeshFromMemory(bytes, binary ? "glb" : "gltf", binary ? "fuzz.glb" : "fuzz.gltf"); });
    return 0;
}
