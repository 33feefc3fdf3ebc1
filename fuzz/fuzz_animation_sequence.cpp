// Fuzz target: mesh-animation sequences through loadMeshSequence (sequence_loader.h),
// which reads files. The input is
//     EXT\n POSE ~~~\n POSE [~~~\n POSE]
// (EXT one of obj, off, ply, stl; default obj): 1 to 3 pose files, written to this
// process's scratch folder and loaded as one sequence on one thread. Expected outcome
// for bad data: MeshLoadError.
#include "fuzz_support.h"

#include "core/animation/sequence_loader.h"
#include "core/mesh/mesh_load_error.h"

#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    std::string_view rest = trimlab::fuzz::bytesOf(data, size);
    std::string extension = "obj";
    const std::size_t newline = rest.find('\n');
    if (newline != std::string_view::npos) {
        const std::string_view first = rest.substr(0, newline);
        if (first == "obj" || first == "off" || first == "ply" || first == "stl") {
            extension = std::string(first);
            rest.remove_prefix(newline + 1);
        }
    }
    static constexpr std::string_view kSeparator = "~~~\n";
    std::vector<std::filesystem::path> files;
    for (int pose = 0; pose < 3; ++pose) {
        const std::size_t cut = pose < 2 ? rest.find(kSeparator) : std::string_view::npos;
        const std::string name = "pose_" + std::to_string(pose) + "." + extension;
        files.push_back(trimlab::fuzz::writeScratchFile(name, rest.substr(0, cut)));
        if (cut == std::string_view::npos)
            break;
        rest.remove_prefix(cut + kSeparator.size());
    }
    trimlab::fuzz::expectTypedErrors<trimlab::MeshLoadError>([&] { (void)trimlab::loadMeshSequence(files, {}, 1); });
    return 0;
}
