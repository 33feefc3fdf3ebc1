#include "core/timeline/frame_export.h"

#include "core/mesh/obj_writer.h"

#include <cstdio>
#include <stdexcept>

namespace trimlab::timeline {

namespace {

std::string frameFileName(const std::string& baseName, int f)
{
    char number[16];
    std::snprintf(number, sizeof number, "%04d", f);
    return baseName + "_" + number + ".obj";
}

} // namespace

std::vector<std::filesystem::path> exportObjSequence(const Timeline& timeline, const std::filesystem::path& directory,
                                                     const std::string& baseName)
{
    if (baseName.empty() || baseName.find_first_of("/\\") != std::string::npos)
        throw std::invalid_argument("exportObjSequence: the base name '" + baseName +
                                    "' must be a non-empty file name without folders");
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error)
        throw std::runtime_error("cannot create the folder " + directory.string() + ": " + error.message());
    std::vector<std::filesystem::path> written;
    // Walk the history once instead of reconstructing every frame from the base.
    TriangleMesh mesh = timeline.base();
    for (int f = 0; f < timeline.frameCount(); ++f) {
        if (f > 0) {
            const Frame& frame = timeline.frame(f);
            for (std::size_t k = 0; k < frame.vertices.size(); ++k)
                mesh.positions[frame.vertices[k]] = frame.after[k];
        }
        const std::filesystem::path path = directory / frameFileName(baseName, f);
        saveMeshObj(path, mesh, {}, "frame " + std::to_string(f) + " of the deformation history");
        written.push_back(path);
    }
    return written;
}

} // namespace trimlab::timeline
