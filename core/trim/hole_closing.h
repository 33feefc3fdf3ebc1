#pragma once
/// \file
/// Closing holes so that the trim rules apply (core/mesh/hole_fans.h), with a check that
/// says where a fan passes through the mesh. Why the check: a fan is a cap through the
/// centroid of its loop; on a small, nearly planar hole it only seals the hole, but on a
/// narrow or twisted loop (or a pose that folds the rim inward) it may cross the surface,
/// and the points between the crossing and the hole get a winding number off by one — a
/// wrong trim there with no visible cause. The thesis's captured animations have such
/// holes (walking-cat's slit, horse-collapse's folding hooves), and refusing them would
/// leave them untrimmable, so the fans are applied and the crossing is reported with the
/// hole, the triangle and the pose named: the user knows where not to trust the trim.
///
/// The test runs in double precision on the watertight ray–triangle test
/// (ray_triangle.h): each spoke of a fan (from a loop corner to the centre) against the
/// mesh triangles whose boxes meet the fan's box, and each edge of those triangles
/// against the fan's triangles. Triangles that share the tested segment's start vertex
/// are skipped (they touch it there by construction).

#include "core/mesh/hole_fans.h"
#include "core/mesh/triangle_mesh.h"
#include "core/util/parameter_spec.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace trimlab {

/// The one row of closing holes on loading, for the verbs that load meshes or animations
/// (render, trim, info, segment, skin, skeleton) and the Python module's keyword.
namespace hole_closing_parameters {

inline constexpr ParameterSpec kCloseHoles{
    .id = "close-holes",
    .flag = "close-holes",
    .settingsKey = "",
    .kind = ParameterKind::Boolean,
    .min = 0,
    .max = 1,
    .defaultValue = 0,
    .help = "Close each hole of an open mesh or animation by a fan to its centroid, so that the trim rules apply "
            "(a fan that crosses the surface is reported)",
    .switchFlag = true,
};
static_assert(isWellFormed(kCloseHoles));

} // namespace hole_closing_parameters

/// Where a fan crosses the mesh: the loop it closes and the mesh triangle it passes.
struct FanCrossing {
    std::size_t loop = 0;
    std::size_t meshTriangle = 0;
};

/// The first crossing of a fan of `fans` with a triangle of the open mesh `triangles`
/// whose vertices are `positions` (withHoleCentres: the open mesh's then the centres);
/// nullopt when no fan crosses the mesh.
[[nodiscard]] std::optional<FanCrossing> firstFanCrossing(const HoleFans& fans, std::span<const glm::uvec3> triangles,
                                                          std::span<const glm::vec3> positions);

/// The warning of `crossing`: the hole (its size and first corner), the triangle its fan
/// crosses, and what that means: "the fan closing the hole of 16 edges at vertex 2017
/// crosses triangle 3619, so the trim may be wrong between them (fill that hole in a mesh
/// editor to be sure)".
[[nodiscard]] std::string fanCrossingMessage(const HoleFans& fans, const FanCrossing& crossing);

/// What closing did: holes closed, the boundary edges they had, and the first fan that
/// crosses the surface (its warning, with the pose or object where it happens) with the
/// number of meshes — poses of an animation, objects of a scene — where fans cross.
struct HoleClosing {
    std::size_t holes = 0;
    std::size_t edges = 0;
    std::string crossing; ///< "" when no fan crosses
    std::size_t crossingMeshes = 0;

    HoleClosing& operator+=(const HoleClosing& other);
};

/// "1 hole of 20 edges", "3 holes of 57 edges", "no holes"; then the crossing's warning
/// when there is one ("2 holes of 19 edges; warning: pose 3: the fan closing ...", with
/// "(fans cross in 5 poses or objects)" when there are more).
[[nodiscard]] std::string holeClosingText(const HoleClosing& closing);

/// `mesh` with its holes closed by fans (closeHoles) and into `closing` what was closed,
/// the first crossing of a fan included (prefixed by `where`, e.g. "pose 3: "). Throws
/// std::invalid_argument as boundaryLoops does when the boundary edges do not form loops.
[[nodiscard]] TriangleMesh closedMesh(const TriangleMesh& mesh, HoleClosing* closing = nullptr,
                                      const std::string& where = {});

} // namespace trimlab
