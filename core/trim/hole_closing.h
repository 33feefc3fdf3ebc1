#pragma once
/// \file
/// Closing holes so that the trim rules apply (core/mesh/hole_fans.h), refusing a fan that
/// would pass through the mesh. Why the check: a fan is a cap through the centroid of
/// its loop; on a small, nearly planar hole it only seals the hole, but on a long twisted
/// loop (or a pose that folds the rim inward) it may cross the surface, and every point
/// between the crossing and the hole would get a winding number off by one — a wrong
/// trim with no visible cause. The check is what a user needs to trust the closed mesh:
/// a fan that crosses is refused with the hole it closes named, never applied silently.
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
            "(refused where a fan would cross the surface)",
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

/// The refusal of `crossing`: the hole (its size and first corner), the triangle it
/// would cross, and what to do instead.
[[nodiscard]] std::string fanCrossingMessage(const HoleFans& fans, const FanCrossing& crossing);

/// What closing did: holes closed and the boundary edges they had.
struct HoleClosing {
    std::size_t holes = 0;
    std::size_t edges = 0;

    HoleClosing& operator+=(const HoleClosing& other);
};

/// "1 hole of 20 edges", "3 holes of 57 edges", "no holes".
[[nodiscard]] std::string holeClosingText(const HoleClosing& closing);

/// `mesh` with its holes closed by fans (closeHoles) and what was closed. Throws
/// std::invalid_argument naming the hole when a fan crosses the mesh ("the fan closing
/// the hole of 20 edges at vertex 812 would cross triangle 4051 ...") and as
/// boundaryLoops does when the boundary edges do not form loops.
[[nodiscard]] TriangleMesh closedMesh(const TriangleMesh& mesh, HoleClosing* closing = nullptr);

} // namespace trimlab
