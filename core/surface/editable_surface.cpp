#include "core/surface/editable_surface.h"

#include "core/surface/nurbs_tessellation.h"
#include "core/surface/subdivision_surface.h"
#include "core/mesh/mesh_validation.h"
#include "core/util/memory_budget.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

namespace trimlab {

// The precomputed tables of one kind: a NURBS tessellation with the working copy of the
// surface whose points it was last evaluated at, or a subdivision surface.
struct EditableSurface::Evaluator {
    std::optional<NurbsTessellation> nurbs;
    NurbsSurface nurbsWork;
    std::optional<SubdivisionSurface> subdivision;

    [[nodiscard]] const TriangleMesh& mesh() const { return nurbs ? nurbs->mesh() : subdivision->mesh(); }
    [[nodiscard]] const std::vector<glm::vec3>& normals() const
    {
        return nurbs ? nurbs->normals() : subdivision->normals();
    }
};

namespace {

void requireFinite(std::span<const glm::dvec3> points, const char* caller)
{
    for (std::size_t c = 0; c < points.size(); ++c) {
        const glm::dvec3& p = points[c];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw std::invalid_argument(std::string(caller) + ": control point " + std::to_string(c) +
                                        " is not finite");
    }
}

std::vector<ControlNetEdge> nurbsNetEdges(const SurfaceDefinition& definition)
{
    const NurbsSurface& s = definition.nurbs().surface;
    std::vector<ControlNetEdge> edges;
    const auto add = [&](std::size_t a, std::size_t b) {
        const std::vector<std::uint32_t> tied = tiedControlPoints(definition, std::uint32_t(a));
        if (std::binary_search(tied.begin(), tied.end(), std::uint32_t(b)))
            return; // two points of one pole: a zero-length edge
        edges.push_back({std::uint32_t(std::min(a, b)), std::uint32_t(std::max(a, b))});
    };
    for (int j = 0; j < s.countV; ++j)
        for (int i = 0; i < s.countU; ++i) {
            if (i + 1 < s.countU)
                add(s.index(i, j), s.index(i + 1, j));
            if (j + 1 < s.countV)
                add(s.index(i, j), s.index(i, j + 1));
        }
    return edges;
}

std::vector<ControlNetEdge> cageNetEdges(const SubdivisionCage& cage)
{
    std::vector<ControlNetEdge> edges;
    std::size_t start = 0;
    for (const std::uint32_t size : cage.faceSizes) {
        for (std::size_t k = 0; k < size; ++k) {
            const std::uint32_t a = cage.faceIndices[start + k];
            const std::uint32_t b = cage.faceIndices[start + (k + 1) % size];
            edges.push_back({std::min(a, b), std::max(a, b)});
        }
        start += size;
    }
    return edges;
}

void sortUnique(std::vector<ControlNetEdge>& edges)
{
    const auto less = [](const ControlNetEdge& x, const ControlNetEdge& y) {
        return x.a != y.a ? x.a < y.a : x.b < y.b;
    };
    std::sort(edges.begin(), edges.end(), less);
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
}

} // namespace

namespace {

/// At most how many triangles the tessellation has: 2·segU·segV for NURBS; for a cage at
/// level L ≥ 1, 2·n·4^(L−1) per face of n corners (exact for Catmull-Clark, 1.5 times too
/// many for Loop's triangles), at most n per face at level 0.
std::uint64_t tessellationTriangleBound(const SurfaceDefinition& definition)
{
    if (definition.kind() == SurfaceKind::Nurbs)
        return 2 * std::uint64_t(definition.nurbs().segmentsU) * std::uint64_t(definition.nurbs().segmentsV);
    const SubdivisionDefinition& subdivision = definition.subdivision();
    const int level = subdivision.settings.level;
    std::uint64_t corners = 0;
    for (const std::uint32_t size : subdivision.cage.faceSizes)
        corners += size;
    if (level <= 0)
        return corners;
    return 2 * corners * (std::uint64_t(1) << (2 * (level - 1)));
}

} // namespace

EditableSurface::EditableSurface(SurfaceDefinition definition)
    : m_definition(std::move(definition)), m_evaluator(std::make_unique<Evaluator>())
{
    requireValidSurfaceDefinition(m_definition, "EditableSurface");
    // About 200 bytes per triangle: the mesh, its normals, the evaluator's stencils or
    // basis tables, and the undo copies of the positions.
    requireMemory(tessellationTriangleBound(m_definition) * 200,
                  "tessellating the " + std::string(surfaceKindName(m_definition.kind())) + " surface into about " +
                      std::to_string(tessellationTriangleBound(m_definition)) + " triangles",
                  m_definition.kind() == SurfaceKind::Nurbs ? "use fewer tessellation segments"
                                                            : "use a lower subdivision level");
    try {
        if (m_definition.kind() == SurfaceKind::Nurbs) {
            const NurbsDefinition& nurbs = m_definition.nurbs();
            m_evaluator->nurbsWork = nurbs.surface;
            m_evaluator->nurbs.emplace(nurbs.surface, nurbs.segmentsU, nurbs.segmentsV);
            m_edges = nurbsNetEdges(m_definition);
        } else {
            const SubdivisionDefinition& subdivision = m_definition.subdivision();
            m_evaluator->subdivision.emplace(subdivision.cage, subdivision.settings);
            m_edges = cageNetEdges(subdivision.cage);
        }
    } catch (const std::invalid_argument& error) {
        throw std::invalid_argument(std::string("EditableSurface: ") + error.what());
    } catch (const SubdivisionError& error) {
        throw std::invalid_argument(std::string("EditableSurface: ") + error.what());
    }
    // A net or cage that tessellates to nothing drawable is refused here, before any view
    // renders an empty picture of it.
    if (const std::string reason = unusableGeometryReason(m_evaluator->mesh()); !reason.empty())
        throw std::invalid_argument("the " + std::string(surfaceKindName(m_definition.kind())) +
                                    " surface's tessellation is unusable: " + reason);
    sortUnique(m_edges);
    m_control = m_definition.controlPoints();
}

EditableSurface::~EditableSurface() = default;
EditableSurface::EditableSurface(EditableSurface&&) noexcept = default;
EditableSurface& EditableSurface::operator=(EditableSurface&&) noexcept = default;

const TriangleMesh& EditableSurface::mesh() const
{
    return m_evaluator->mesh();
}

const std::vector<glm::vec3>& EditableSurface::normals() const
{
    return m_evaluator->normals();
}

void EditableSurface::setControlPoints(std::span<const glm::dvec3> points)
{
    if (points.size() != m_control.size())
        throw std::invalid_argument("EditableSurface::setControlPoints: " + std::to_string(points.size()) +
                                    " points given, the surface has " + std::to_string(m_control.size()));
    requireFinite(points, "EditableSurface::setControlPoints");
    if (m_evaluator->nurbs) {
        NurbsSurface next = m_evaluator->nurbsWork;
        next.points.assign(points.begin(), points.end());
        m_evaluator->nurbs->update(next); // throws on a broken tie, changing nothing
        m_evaluator->nurbsWork = std::move(next);
    } else {
        m_evaluator->subdivision->evaluate(points);
    }
    m_control.assign(points.begin(), points.end());
}

std::vector<std::uint32_t> EditableSurface::moveControlPoints(std::span<const std::uint32_t> indices,
                                                              std::span<const glm::dvec3> positions)
{
    const char* caller = "EditableSurface::moveControlPoints";
    if (indices.size() != positions.size())
        throw std::invalid_argument(std::string(caller) + ": " + std::to_string(indices.size()) + " indices but " +
                                    std::to_string(positions.size()) + " positions");
    requireFinite(positions, caller);
    std::vector<glm::dvec3> next = m_control;
    for (std::size_t k = 0; k < indices.size(); ++k) {
        if (indices[k] >= m_control.size() || (k > 0 && indices[k] <= indices[k - 1]))
            throw std::invalid_argument(std::string(caller) + ": index " + std::to_string(indices[k]) +
                                        " is out of range or not sorted ascending and unique");
        next[indices[k]] = positions[k];
    }
    std::vector<std::uint32_t> changed;
    if (m_evaluator->nurbs) {
        NurbsSurface work = m_evaluator->nurbsWork;
        work.points = next;
        const std::vector<std::size_t> moved(indices.begin(), indices.end());
        changed = m_evaluator->nurbs->update(work, moved);
        m_evaluator->nurbsWork = std::move(work);
    } else {
        changed = m_evaluator->subdivision->update(next, indices);
    }
    m_control = std::move(next);
    return changed;
}

std::vector<std::uint32_t> EditableSurface::support(std::uint32_t c) const
{
    if (c >= m_control.size())
        throw std::out_of_range("EditableSurface::support: control point " + std::to_string(c) +
                                " does not exist (the surface has " + std::to_string(m_control.size()) + ")");
    if (m_evaluator->nurbs)
        return m_evaluator->nurbs->support(c);
    const std::span<const std::uint32_t> s = m_evaluator->subdivision->support(c);
    return {s.begin(), s.end()};
}

std::vector<std::uint32_t> EditableSurface::tiedPoints(std::uint32_t c) const
{
    return tiedControlPoints(m_definition, c);
}

const SubdivisionSurface* EditableSurface::subdivision() const
{
    return m_evaluator->subdivision ? &*m_evaluator->subdivision : nullptr;
}

glm::dvec3 EditableSurface::controlPointNormal(std::uint32_t c) const
{
    const std::vector<glm::vec3>& normals = this->normals();
    glm::dvec3 sum(0.0);
    for (const std::uint32_t v : support(c))
        sum += glm::dvec3(normals[v]);
    const double length = std::sqrt(sum.x * sum.x + sum.y * sum.y + sum.z * sum.z);
    if (!(length > 1e-12) || !std::isfinite(length))
        return glm::dvec3(0.0);
    return sum / length;
}

} // namespace trimlab
