#pragma once
/// \file
/// Where an animation rig is rooted: at the pelvis for bipeds and quadrupeds, at the
/// body's centre of mass otherwise. Animators pose a character from its hips; a root
/// at a neck hub makes the legs children of the head.
///
/// The pelvis is where a pair of limbs leaves at the end of the body. Around each node
/// lie its parts (what the graph falls into without the node, weighed by the vertices
/// they hold, heaviest first). A node has a pair of limbs when it has at least three
/// parts and its third holds at least 4 % of the vertices and half of its second (two
/// limbs alike: legs, or arms; a tail or a head alone makes no pair). Of the nodes with
/// a pair, the pelvis has the heaviest first part: the hips have the whole upper body,
/// the arms and the head on one side, the shoulders only the trunk and the legs. Without
/// a pair, the root is the junction (three parts or more) whose largest part is the
/// lightest, the hub nearest the centre of mass; without a junction (a snake), the node
/// whose largest part is the lightest.

#include <cstddef>
#include <span>
#include <vector>

namespace trimlab {

/// Two limbs are alike (a pair) when the lighter holds at least this fraction of the
/// heavier; bone_names.h names such pairs L and R.
inline constexpr double kLikeLimbs = 0.5;

/// The root node of a graph (`adjacent[k]`: the neighbours of node k, each edge listed
/// at both ends) whose node k holds `mass[k]` vertices, as described above; ties go to
/// the lower index. 0 for an empty graph. Throws std::invalid_argument if the sizes
/// differ. O(N·(N + E)).
[[nodiscard]] int bodyRoot(const std::vector<std::vector<int>>& adjacent, std::span<const std::size_t> mass);

} // namespace trimlab
