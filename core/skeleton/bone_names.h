#pragma once
/// \file
/// Names for the bones of a rig that an animator can read in Blender's outliner or a
/// game engine's joint list: `spine_1`, `leg_L_2`, `arm_R_1`, … instead of bone numbers.
///
/// The rig is walked from its root; a chain of bones runs from a junction (or the root)
/// to the next junction or a leaf, and its bones are numbered 1, 2, … from its start.
/// - At the root, the heaviest part (by the vertices the joints' regions hold) is the
///   `spine`. When the next two are a pair of like limbs (the lighter holds at least half
///   of the heavier) they are the legs, `leg_L` and `leg_R`; the
///   next part is the `tail` and any others are `root_branch_1`, `root_branch_2`, … .
/// - At a junction the straightest continuation of the chain's last bone keeps the
///   chain's name (the neck goes on from the spine, an arm leaves it). On the spine, when
///   the two heaviest of the other parts are the first pair of like limbs above the legs,
///   they are `arm_L` and `arm_R`. Any other part is `<chain>_<i>_branch_<k>` (branch k,
///   by decreasing weight, at the end of the chain's bone i: `spine_3_branch_1_2` is the
///   second bone of the first branch leaving the end of spine_3).
/// - Left and right: of the two tips of a pair, the one farther along the coordinate axis
///   on which they differ most is L (Blender's convention: a character faces −Y, its left
///   is +X). Which axis is the body's lateral one is not known from the rig alone; on a
///   model that faces another way the sides may be swapped, and the names still pair up.

#include "core/skeleton/skeleton.h"

#include <string>
#include <vector>

namespace trimlab {

/// One unique name per bone of `rig`, in bone order (see above). An empty rig has none.
[[nodiscard]] std::vector<std::string> boneNames(const SkeletonRig& rig);

} // namespace trimlab
