#include "core/animation/sequence_loader.h"

#include "core/util/parallel_for.h"
#include "core/animation/pose_topology.h"
#include "core/mesh/mesh_io.h"
#include "core/util/memory_budget.h"

#include <exception>
#include <stdexcept>

namespace trimlab {

MeshAnimation loadMeshSequence(const std::vector<std::filesystem::path>& files, const TaskControl& control,
                               unsigned threads)
{
    if (files.empty())
        throw std::invalid_argument("loadMeshSequence: no files");
    control.throwIfCancelled();
    MeshAnimation animation;
    TriangleMesh first = loadMesh(files.front());
    animation.triangles = std::move(first.triangles);
    // Every pose has the first one's size (checked below): the total is known now.
    requireMemory(std::uint64_t(files.size()) * first.positions.size() * sizeof(glm::vec3),
                  files.front().parent_path().string() + ": loading " + std::to_string(files.size()) + " poses of " +
                      std::to_string(first.positions.size()) + " vertices",
                  "load fewer poses (a pattern or folder with fewer files)");
    animation.poses.resize(files.size());
    animation.poses.front() = std::move(first.positions);
    const std::size_t vertexCount = animation.poses.front().size();
    // Errors are kept per file so that the first bad file in sequence order is reported,
    // whichever thread found its problem first.
    std::vector<std::exception_ptr> errors(files.size());
    // Item 0 is the first file, loaded above: the progress counts every file of the
    // sequence ("48 of 48"), not the ones left after the first ("47 of 47").
    parallelFor(
        files.size(), threads,
        [&](std::size_t i) {
            if (i == 0)
                return;
            try {
                TriangleMesh pose = loadMesh(files[i]);
                requireSameTopology(animation.triangles, vertexCount, pose, files[i].string());
                animation.poses[i] = std::move(pose.positions);
            } catch (...) {
                errors[i] = std::current_exception();
            }
        },
        control, "load");
    for (const std::exception_ptr& error : errors) {
        if (error)
            std::rethrow_exception(error);
    }
    for (const std::filesystem::path& file : files)
        animation.poseNames.push_back(file.filename().string());
    return animation;
}

} // namespace trimlab
