// Fuzz target: glTF animations (morph targets, skins, animated nodes) through
// readGltfAnimation (gltf_animation.h), sampled at the keyframes and at 10 fps. Input
// starting with "glTF" is a GLB, anything else JSON; gzip data is unpacked first.
// Expected outcome for bad data: MeshLoadError.
#include "fuzz_support.h"

#include "core/animation/gltf_animation.h"
#include "core/mesh/mesh_load_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view bytes = trimlab::fuzz::bytesOf(data, size);
    for (const double fps : {0.0, 10.0}) {
        trimlab::GltfAnimationOptions options;
        options.fps = fps;
        trimlab::fuzz::expectTypedErrors<trimlab::MeshLoadError>(
            [&] { (void)trimlab::readGltfAnimation(bytes, "fuzz.gltf", {}, options); });
    }
    return 0;
}
