#pragma once
/// \file
/// A pose of object 0 as the view shows it: always the CPU's positions — what the exact
/// reference, the CPU still, Fit and every readout of "what is shown" use — and, where the
/// GPU can compute the same positions itself, what it computes them from: a skinned model
/// and a pose index (frame/gpu_skinning.h) or subdivision stencils and control points
/// (frame/gpu_subdivision.h). The renderer tries the GPU's way first and uploads the
/// positions where it cannot (gpu_pose_evaluator.h), so both ways show the same mesh.

#include "render/frame/subdivision_stencils.h"

#include "core/skinning/skinning_model.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <memory>
#include <variant>
#include <vector>

namespace trimlab::render {

/// Pose `pose` of `model`, a skinning of object 0's mesh.
struct SkinnedPose {
    std::shared_ptr<const SkinningModel> model;
    std::size_t pose = 0;
};

/// The subdivision surface `stencils` were taken from at `controlPoints` (#C).
struct SubdivisionPose {
    std::shared_ptr<const SubdivisionStencils> stencils;
    std::vector<glm::dvec3> controlPoints;
};

/// Object 0's pose: `positions` (#V, object space) and how the GPU may evaluate them.
struct ShownPose {
    std::vector<glm::vec3> positions;
    /// std::monostate: the positions are uploaded as they are.
    std::variant<std::monostate, SkinnedPose, SubdivisionPose> evaluation;
};

} // namespace trimlab::render
