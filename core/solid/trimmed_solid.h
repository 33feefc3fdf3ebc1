#pragma once
/// \file
/// The trimmed solid as exact geometry: what the viewport shows under a static rule or a
/// CSG expression, as a closed triangle mesh for printing, meshing or another CAD tool.
/// The scene's triangles are refined along all their intersections (exact arithmetic),
/// every cell of space gets its winding number per object, and the faces where the
/// classification changes are kept, turned so that they face out of the kept cells.
/// Where the kept cells touch along an edge (more than two kept faces meet there) the
/// result is non-manifold; those edges are counted, not repaired.

#include "core/mesh/triangle_mesh.h"
#include "core/solid/exact_profile.h"
#include "core/scene/scene.h"
#include "core/trim/trim_settings.h"
#include "core/util/task_control.h"

#include <cstddef>

namespace trimlab {

struct TrimmedSolidStats {
    std::size_t inputTriangles = 0;
    std::size_t degenerateTriangles = 0; ///< zero-area input triangles (they bound nothing)
    std::size_t refinedFaces = 0;        ///< faces of the arrangement after refinement
    std::size_t cancelledFaces = 0;      ///< coincident faces of opposite orientation that cancel
    std::size_t boundaryPieces = 0;      ///< connected boundary pieces of the cells
    std::size_t components = 0;          ///< connected pieces of the arrangement
    std::size_t contradictions = 0;      ///< faces with inconsistent windings (0 for closed input)
    std::size_t keptFaces = 0;           ///< faces between kept and dropped cells (before rounding)
    /// Rounding to float: exact vertices that fell on one float position (merged), and
    /// the kept faces that collapsed with them (dropped).
    std::size_t roundingMergedVertices = 0;
    std::size_t roundingDroppedFaces = 0;
    std::size_t nonManifoldEdges = 0; ///< edges of the result with more than two faces
    std::size_t openEdges = 0;        ///< edges of the result with one face (0: closed)
    double signedVolume = 0.0;        ///< of the result as written (float positions), in world units³
    double refineMs = 0.0;
    double windingMs = 0.0;
    ExactProfile profile; ///< the stages of refineMs and windingMs
};

struct TrimmedSolid {
    /// World-space result; positions rounded to float from the exact points (points on one
    /// float position merged, faces that collapse dropped).
    TriangleMesh mesh;
    TrimmedSolidStats stats;
};

/// The solid `settings` keeps of `scene`: the cells settings.rule keeps by the scene's
/// winding number, or with a CSG expression the cells it keeps by each object's own rule
/// (TrimSettings::objectRule). Clipping, caps and highlights play no part. Throws
/// std::invalid_argument when trimming is off (no rule: no solid), OperationCancelled
/// when `control` asks.
[[nodiscard]] TrimmedSolid trimmedSolid(const Scene& scene, const TrimSettings& settings,
                                        const TaskControl& control = {});

/// The solid as a view cut by the enabled clipping planes of settings.clipSet() and capped
/// shows it: trimmedSolid's solid intersected with the part of space every enabled plane
/// keeps, so that it is closed on each plane by a cap (the faces of the clip polytope,
/// clip_polytope.h, inside the solid). The same cells, winding numbers and rule as
/// trimmedSolid, with the polytope as one more operand in the arrangement; with no plane
/// enabled it is trimmedSolid's solid. Throws as trimmedSolid does.
[[nodiscard]] TrimmedSolid cutTrimmedSolid(const Scene& scene, const TrimSettings& settings,
                                           const TaskControl& control = {});

} // namespace trimlab
