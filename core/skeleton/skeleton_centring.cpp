#include "core/skeleton/skeleton_centring.h"

#include "core/skeleton/half_sphere_directions.h"
#include "core/skeleton/leaf_extension.h"
#include "core/util/parallel_for.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace trimlab {

namespace {

// A leaf's chords are looked for in the plane square to its bone, this many directions
// over half a turn (antipodal pairs): the nearest wall is then a side of its limb, never
// the tip ahead or the limb behind. With 16, a leaf 0.16 off the axis of the test's
// capsule (radius 0.3) ends within 0.0001 of it.
constexpr int kAcrossDirections = 16;

// The midpoint of the chord through p towards its nearest wall; none where the first
// direction, or one whose wall is nearer than all before it, finds no surface on a side.
// Each ray asks only for crossings nearer than the nearest wall so far, which most
// directions have none of (their queries open few boxes); the other side of a nearer one
// is then traced in full for the chord. The answer is the one every ray traced in full
// gives, except that a direction whose walls are both beyond the nearest is not asked
// whether it has walls at all: inside a closed mesh every ray has (the node is inside,
// checked by the caller, and the triangle test is watertight).
std::optional<glm::dvec3> nearestWallChordMidpoint(const glm::dvec3& p, const PointInMesh& solid,
                                                   const std::vector<glm::dvec3>& directions)
{
    double nearest = std::numeric_limits<double>::infinity();
    std::optional<glm::dvec3> midpoint;
    for (const glm::dvec3& d : directions) {
        std::optional<double> a = solid.nearestCrossing(p, d, 0.0, nearest);
        std::optional<double> b = solid.nearestCrossing(p, -d, 0.0, nearest);
        if (!a && !b && nearest < std::numeric_limits<double>::infinity())
            continue; // both walls at least as far as the nearest: not a nearer one
        if (!a)
            a = solid.nearestCrossing(p, d, 0.0);
        if (!b)
            b = solid.nearestCrossing(p, -d, 0.0);
        if (!a || !b)
            return std::nullopt; // p is not enclosed: leave it
        if (std::min(*a, *b) < nearest) {
            nearest = std::min(*a, *b);
            midpoint = p + 0.5 * (*a - *b) * d;
        }
    }
    return midpoint;
}

// kAcrossDirections unit vectors square to `bone` (a unit vector), over half a turn.
std::vector<glm::dvec3> directionsAcross(const glm::dvec3& bone)
{
    // Any vector not parallel to the bone gives the plane's first axis.
    const glm::dvec3 helper = std::abs(bone.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
    const glm::dvec3 first = glm::normalize(glm::cross(bone, helper));
    const glm::dvec3 second = glm::cross(bone, first);
    std::vector<glm::dvec3> across;
    for (int i = 0; i < kAcrossDirections; ++i) {
        const double angle = std::numbers::pi * double(i) / double(kAcrossDirections);
        across.push_back(std::cos(angle) * first + std::sin(angle) * second);
    }
    return across;
}

} // namespace

glm::dvec3 leafCentredAcrossItsBone(const glm::dvec3& parent, const glm::dvec3& leaf, const PointInMesh& solid,
                                    int rounds)
{
    const double length = glm::length(leaf - parent);
    if (!(length > 0.0) || !solid.contains(leaf))
        return leaf;
    const std::vector<glm::dvec3> across = directionsAcross((leaf - parent) / length);
    glm::dvec3 p = leaf;
    for (int round = 0; round < rounds; ++round) {
        const std::optional<glm::dvec3> next = nearestWallChordMidpoint(p, solid, across);
        if (!next || !solid.contains(*next) || !solid.segmentInside(parent, *next))
            break;
        p = *next;
    }
    return p;
}

std::size_t centreLeavesAcrossTheirBones(CurveSkeleton& curve, const PointInMesh& solid, const CentringOptions& options)
{
    const std::vector<int> neighbour = leafNeighbours(curve);
    std::vector<char> moved(curve.nodes.size(), 0);
    parallelFor(curve.nodes.size(), 0, [&](std::size_t k) {
        if (neighbour[k] < 0)
            return;
        const glm::dvec3 centred = leafCentredAcrossItsBone(curve.nodes[static_cast<std::size_t>(neighbour[k])],
                                                            curve.nodes[k], solid, options.rounds);
        moved[k] = centred != curve.nodes[k];
        curve.nodes[k] = centred;
    });
    return static_cast<std::size_t>(std::count(moved.begin(), moved.end(), 1));
}

std::size_t centreOnNearestWallChords(CurveSkeleton& curve, const PointInMesh& solid, const CentringOptions& options,
                                      const std::vector<char>& keep)
{
    if (!keep.empty() && keep.size() != curve.nodes.size())
        throw std::invalid_argument("centring the skeleton: " + std::to_string(keep.size()) + " keep flags for " +
                                    std::to_string(curve.nodes.size()) + " nodes");
    const std::vector<glm::dvec3> directions = halfSphereDirections(std::max(1, options.directions));
    std::vector<char> moved(curve.nodes.size(), 0);
    std::vector<int> degree(curve.nodes.size(), 0);
    for (const std::array<int, 2>& edge : curve.edges) {
        ++degree[static_cast<std::size_t>(edge[0])];
        ++degree[static_cast<std::size_t>(edge[1])];
    }
    parallelFor(curve.nodes.size(), 0, [&](std::size_t k) {
        glm::dvec3 p = curve.nodes[k];
        if ((!keep.empty() && keep[k]) || !solid.contains(p) || (options.keepLeaves && degree[k] == 1))
            return;
        for (int round = 0; round < options.rounds; ++round) {
            const std::optional<glm::dvec3> next = nearestWallChordMidpoint(p, solid, directions);
            if (!next || !solid.contains(*next))
                break;
            p = *next;
            moved[k] = 1;
        }
        curve.nodes[k] = p;
    });
    return static_cast<std::size_t>(std::count(moved.begin(), moved.end(), 1));
}

} // namespace trimlab
