#include "python/animation_arguments.h"

#include "python/array_convert.h"
#include "python/keyword_parameters.h"
#include "python/python_errors.h"

#include "core/animation/animation_load_parameters.h"

#include <stdexcept>
#include <string>

namespace trimlab::python {

MeshAnimation animationFromArrays(py::handle poses, py::handle triangles, py::handle restPose)
{
    MeshAnimation animation;
    animation.poses = posesFromArray(poses, "poses");
    if (animation.poses.empty())
        throw InputError("poses must hold at least one pose, got shape (0, ...)");
    animation.triangles = trianglesFromArray(triangles, animation.vertexCount(), "F");
    for (std::size_t k = 0; k < animation.poses.size(); ++k)
        animation.poseNames.push_back("pose " + std::to_string(k));
    const ParameterSpec& restSpec = animation_load_parameters::kRestPose;
    animation.restPose = std::size_t(restPose.is_none() ? int(restSpec.defaultValue) : keywordInt(restSpec, restPose));
    if (animation.restPose >= animation.poses.size())
        throw ParameterError("the rest pose " + std::to_string(animation.restPose) +
                             " does not exist; the animation has " + std::to_string(animation.poses.size()) +
                             " poses (0 to " + std::to_string(animation.poses.size() - 1) + ")");
    try {
        requireWellFormed(animation);
    } catch (const std::invalid_argument& e) {
        throw InputError(e.what());
    }
    return animation;
}

} // namespace trimlab::python
