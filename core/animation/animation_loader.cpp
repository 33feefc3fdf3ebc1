#include "core/animation/animation_loader.h"

#include "core/animation/closed_animation.h"
#include "core/animation/sequence_files.h"
#include "core/animation/sequence_loader.h"
#include "core/mesh/mesh_load_error.h"

#include <stdexcept>

namespace trimlab {

MeshAnimation loadAnimation(const std::string& source, const AnimationLoadOptions& options, const TaskControl& control,
                            HoleClosing* closing)
{
    MeshAnimation animation = isGltfSource(source) ? loadGltfAnimation(source, options.gltf, control)
                                                   : loadMeshSequence(sequenceFiles(source), control, options.threads);
    if (options.restPose >= animation.poseCount())
        throw MeshLoadError(source, "the rest pose " + std::to_string(options.restPose) +
                                        " does not exist; the animation has " + std::to_string(animation.poseCount()) +
                                        " poses (0 to " + std::to_string(animation.poseCount() - 1) + ")");
    animation.restPose = options.restPose;
    if (!options.closeHoles)
        return animation;
    try {
        return closeAnimationHoles(animation, closing);
    } catch (const std::invalid_argument& e) {
        throw MeshLoadError(source, std::string("cannot close its holes: ") + e.what());
    }
}

} // namespace trimlab
