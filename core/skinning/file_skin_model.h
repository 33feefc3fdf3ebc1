#pragma once
/// \file
/// The skin a glTF animation was posed with (core/animation/animation_skin.h) as a
/// SkinningModel, so that the GPU skinning path (render/frame/gpu_skinning.h) can play a
/// skinned glTF file the way it plays a fitted approximation: rest-to-pose linear blend
/// skinning from the bind positions, one bone per joint, the bone transform of pose t the
/// joint matrix world(joint, t)·inverseBind. The bind pose is generally not pose
/// `restPose`, so the rest pose has transforms of its own (restPoseMoves).

#include "core/animation/mesh_animation.h"
#include "core/skinning/skinning_model.h"

#include <optional>

namespace trimlab {

/// nullopt when `animation` has no skin, its skin does not match the animation (vertex or
/// pose counts: poses were dropped since loading), a vertex has more than kMaxInfluences
/// weighted joints, or a joint matrix is not affine (bottom row ≠ 0 0 0 1).
[[nodiscard]] std::optional<SkinningModel> fileSkinningModel(const MeshAnimation& animation);

} // namespace trimlab
