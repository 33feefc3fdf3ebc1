#pragma once
/// \file
/// Internal to skinning_gltf.cpp: the parts of the glTF model the skin and the morph
/// export add to the shared mesh (node 0, mesh 0, primitive 0).

#include "core/skinning/skinning_gltf.h"

#include <tiny_gltf.h>

#include <glm/vec3.hpp>

#include <vector>

namespace trimlab::skinning_gltf {

/// Positions rounded to float, as a file stores them.
[[nodiscard]] std::vector<glm::vec3> toFloat(const std::vector<glm::dvec3>& positions);

/// Skin, skeleton nodes and the TRS animation (skinning_gltf.h). `times`: #P keyframe times.
[[nodiscard]] ExportedSkin addSkin(tinygltf::Model& model, const SkinningModel& skinning,
                                   const std::vector<PosePositions>& target, const std::vector<float>& times,
                                   bool step);

/// One morph target per pose and the STEP weights animation.
[[nodiscard]] ExportedSkin addMorphTargets(tinygltf::Model& model, const SkinningModel& skinning,
                                           const std::vector<float>& times);

} // namespace trimlab::skinning_gltf
