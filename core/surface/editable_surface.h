#pragma once
/// \file
/// An editable surface: the evaluator built once from a SurfaceDefinition (the NURBS
/// tessellation's or the subdivision stencils' precomputed tables) that turns control
/// points into the positions of a trimmable triangle mesh whose connectivity never
/// changes — so every control-point edit is a timeline frame like a brush stroke, and the
/// dynamic rules classify its triangles by whether they moved (thesis 8.1.1–8.2).
///
/// State: the current control points (#C) and the mesh evaluated at them. The document
/// (timeline) is the truth; this object mirrors its last frame: after an undo or redo,
/// call setControlPoints(timeline.currentControlPoints()).
///
/// Not thread-safe: evaluation updates internal tables (one surface per thread).

#include "core/mesh/triangle_mesh.h"
#include "core/surface/surface_definition.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <span>
#include <utility>
#include <vector>

namespace trimlab {

/// One edge of the control net (NURBS: between grid neighbours (i, j)–(i+1, j) and
/// (i, j)–(i, j+1); subdivision: a cage edge), `a < b`, for drawing.
struct ControlNetEdge {
    std::uint32_t a = 0;
    std::uint32_t b = 0;
    friend bool operator==(const ControlNetEdge&, const ControlNetEdge&) = default;
};

class EditableSurface {
public:
    /// Builds the evaluator and evaluates the definition's own control points. Throws
    /// std::invalid_argument "EditableSurface: <problem>" for an invalid definition
    /// (findSurfaceDefinitionProblem) or one the tessellator refuses (too many samples or
    /// triangles), naming the problem.
    explicit EditableSurface(SurfaceDefinition definition);
    ~EditableSurface();
    EditableSurface(EditableSurface&&) noexcept;
    EditableSurface& operator=(EditableSurface&&) noexcept;

    [[nodiscard]] const SurfaceDefinition& definition() const { return m_definition; }
    [[nodiscard]] SurfaceKind kind() const { return m_definition.kind(); }

    /// #C.
    [[nodiscard]] std::size_t controlPointCount() const { return m_control.size(); }
    /// The current #C control points (object space).
    [[nodiscard]] const std::vector<glm::dvec3>& controlPoints() const { return m_control; }
    /// The edges of the control net / cage (unique, sorted by (a, b)). NURBS: edges
    /// joining two points of the same pole are left out (they have length 0); seam
    /// twins keep their edges (they coincide with the twin's, drawn twice, harmless).
    [[nodiscard]] const std::vector<ControlNetEdge>& netEdges() const { return m_edges; }

    /// The tessellated mesh at the current control points (#V float positions, fixed
    /// triangles). Its connectivity is the same for every control point set.
    [[nodiscard]] const TriangleMesh& mesh() const;
    /// #V unit vertex normals of mesh() ((0,0,0) where undefined, never NaN).
    [[nodiscard]] const std::vector<glm::vec3>& normals() const;

    /// Sets all control points (#C, finite; tied NURBS points equal) and re-evaluates
    /// everything. Throws std::invalid_argument for a wrong count, a non-finite point or
    /// a broken tie; on a throw nothing changes.
    void setControlPoints(std::span<const glm::dvec3> points);

    /// Moves the control points `indices` (sorted ascending, unique, < #C) to
    /// `positions` (same size) and re-evaluates only what depends on them. Returns the
    /// union of their supports (sorted ascending): the only vertices whose position may
    /// have changed. Same throws as setControlPoints, plus std::invalid_argument for bad
    /// indices; on a throw nothing changes. The caller must move tied points together
    /// (tiedControlPoints; controlEditFrame does).
    std::vector<std::uint32_t> moveControlPoints(std::span<const std::uint32_t> indices,
                                                 std::span<const glm::dvec3> positions);

    /// The mesh vertices whose position depends on control point `c` (sorted ascending):
    /// exactly those that can move when it moves (NURBS: with its tied points).
    /// std::out_of_range for c >= #C.
    [[nodiscard]] std::vector<std::uint32_t> support(std::uint32_t c) const;
    /// tiedControlPoints(definition(), c).
    [[nodiscard]] std::vector<std::uint32_t> tiedPoints(std::uint32_t c) const;
    /// The evaluator of a subdivision definition, at the current control points (its
    /// stencils, e.g. for the GPU evaluation of render/frame/gpu_subdivision.h); nullptr
    /// for NURBS.
    [[nodiscard]] const SubdivisionSurface* subdivision() const;

    /// The direction "move along normal" uses for control point `c` at the current
    /// control points: the normalised sum of the unit normals of its support vertices
    /// (the surface near the point, facing out of the solid for closed outward surfaces).
    /// Control points lie off the surface, so there is no normal *at* them; this is the
    /// normal of the part of the surface they pull. (0,0,0) when the sum vanishes (never
    /// NaN). std::out_of_range for c >= #C.
    [[nodiscard]] glm::dvec3 controlPointNormal(std::uint32_t c) const;

private:
    struct Evaluator;
    SurfaceDefinition m_definition;
    std::vector<glm::dvec3> m_control;
    std::vector<ControlNetEdge> m_edges;
    std::unique_ptr<Evaluator> m_evaluator;
};

} // namespace trimlab
