#pragma once
/// \file
/// The data that flows between the stages of skeleton extraction by mesh contraction
/// (Berenguer & Moreno, III.A–F): the curve skeleton the simplification produces and the
/// refinement moves, and the animation rig the selection makes of it, which the bone-heat
/// weights, posing and the glTF export consume. Plain data; the algorithms live in their
/// own files beside this one.

#include <glm/vec3.hpp>

#include <array>
#include <vector>

namespace trimlab {

/// A curve skeleton: nodes joined by edges, and which node each mesh vertex collapsed into
/// (the skeleton–mesh correspondence of III.B, the regions Π_k of eq. 11).
struct CurveSkeleton {
    std::vector<glm::dvec3> nodes;         ///< #N positions, in the mesh's units
    std::vector<std::array<int, 2>> edges; ///< undirected, first < second, no duplicates
    std::vector<int> vertexNode;           ///< #V (mesh vertices): the node that absorbed it
};

/// One bone of a rig: the segment from joint `head` to joint `tail`, where head is the
/// tail's parent in the joint tree. A bone rotates about its head and carries every bone
/// below it (its `parentBone` is the bone whose tail is its head; −1 when head is the root).
struct Bone {
    int head = -1;
    int tail = -1;
    int parentBone = -1;
};

/// An animation rig (III.D–F): a tree of joints rooted at `root`, and one bone per
/// non-root joint. Bones are ordered so that a bone's parent comes before it (a
/// breadth-first order from the root), which is the order posing and export walk them.
struct SkeletonRig {
    std::vector<glm::dvec3> joints; ///< #J rest-pose positions
    std::vector<int> parent;        ///< #J, parent joint, −1 for the root
    int root = 0;
    std::vector<Bone> bones;      ///< #J − 1, parents first
    std::vector<int> vertexJoint; ///< #V (mesh vertices): the joint whose region holds it
};

} // namespace trimlab
