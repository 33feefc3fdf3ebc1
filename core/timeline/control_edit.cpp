#include "core/timeline/control_edit.h"

#include "core/util/float_bits.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

namespace trimlab {

namespace {

bool isFinite(const glm::dvec3& p)
{
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// Every target with its tied points, by index; a point given two different positions is
// an error. Points that would not move are dropped.
std::map<std::uint32_t, glm::dvec3> expandTargets(const EditableSurface& surface,
                                                  std::span<const ControlPointTarget> targets)
{
    std::map<std::uint32_t, glm::dvec3> wanted;
    for (std::size_t k = 0; k < targets.size(); ++k) {
        const ControlPointTarget& target = targets[k];
        if (target.index >= surface.controlPointCount())
            throw std::invalid_argument("controlEditFrame: target " + std::to_string(k) + ": control point " +
                                        std::to_string(target.index) + " does not exist (the surface has " +
                                        std::to_string(surface.controlPointCount()) + ")");
        if (!isFinite(target.position))
            throw std::invalid_argument("controlEditFrame: target " + std::to_string(k) +
                                        ": the position of control point " + std::to_string(target.index) +
                                        " is not finite");
        for (const std::uint32_t c : surface.tiedPoints(target.index)) {
            const auto [it, inserted] = wanted.emplace(c, target.position);
            if (!inserted && !sameBits(it->second, target.position))
                throw std::invalid_argument("controlEditFrame: control point " + std::to_string(c) +
                                            " is given two different positions (directly or through a tied point)");
        }
    }
    for (auto it = wanted.begin(); it != wanted.end();) {
        if (sameBits(it->second, surface.controlPoints()[it->first]))
            it = wanted.erase(it);
        else
            ++it;
    }
    return wanted;
}

bool sameFloatBits(const glm::vec3& a, const glm::vec3& b)
{
    return sameBits(a, b);
}

} // namespace

timeline::Timeline surfaceTimeline(const SurfaceDefinition& definition, DynamicRule firstRule)
{
    const EditableSurface surface(definition);
    return timeline::Timeline(surface.mesh(), definition, firstRule);
}

void requireSurfaceMatchesTimeline(const EditableSurface& surface, const timeline::Timeline& history)
{
    if (!history.surface())
        throw std::invalid_argument("the history has no surface definition: it is a plain mesh history");
    if (!(*history.surface() == surface.definition()))
        throw std::invalid_argument("the history's surface definition differs from the edited surface's");
    const TriangleMesh& mesh = surface.mesh();
    if (history.base().positions.size() != mesh.positions.size())
        throw std::invalid_argument("the history's base mesh has " + std::to_string(history.base().positions.size()) +
                                    " vertices, the surface's tessellation " + std::to_string(mesh.positions.size()));
    if (history.base().triangles != mesh.triangles)
        throw std::invalid_argument("the history's base mesh triangles differ from the surface's tessellation");
}

timeline::Frame controlEditFrame(EditableSurface& surface, std::span<const ControlPointTarget> targets,
                                 std::span<const glm::vec3> positionsBefore)
{
    if (positionsBefore.size() != surface.mesh().positions.size())
        throw std::invalid_argument("controlEditFrame: " + std::to_string(positionsBefore.size()) +
                                    " positions before the edit, the surface's mesh has " +
                                    std::to_string(surface.mesh().positions.size()));
    const std::map<std::uint32_t, glm::dvec3> wanted = expandTargets(surface, targets);
    if (wanted.empty())
        throw std::invalid_argument("controlEditFrame: nothing moves (every target is where its control point is)");
    timeline::Frame frame;
    std::vector<std::uint32_t> indices;
    std::vector<glm::dvec3> positions;
    for (const auto& [index, position] : wanted) {
        frame.controlMoves.push_back({index, surface.controlPoints()[index], position});
        indices.push_back(index);
        positions.push_back(position);
    }
    const std::vector<std::uint32_t> candidates = surface.moveControlPoints(indices, positions);
    const std::vector<glm::vec3>& after = surface.mesh().positions;
    for (const std::uint32_t v : candidates) {
        if (sameFloatBits(positionsBefore[v], after[v]))
            continue;
        frame.vertices.push_back(v);
        frame.before.push_back(positionsBefore[v]);
        frame.after.push_back(after[v]);
    }
    return frame;
}

timeline::Frame appendControlEdit(timeline::Timeline& history, EditableSurface& surface,
                                  std::span<const ControlPointTarget> targets)
{
    const std::vector<glm::dvec3>& current = history.currentControlPoints();
    if (!history.surface())
        throw std::invalid_argument("appendControlEdit: the history has no surface definition");
    bool same = current.size() == surface.controlPointCount();
    for (std::size_t c = 0; same && c < current.size(); ++c)
        same = sameBits(current[c], surface.controlPoints()[c]);
    if (!same)
        surface.setControlPoints(current);
    const std::vector<glm::dvec3> previous = surface.controlPoints();
    timeline::Frame frame = controlEditFrame(surface, targets, history.currentPositions());
    try {
        history.appendFrame(frame);
    } catch (...) {
        surface.setControlPoints(previous);
        throw;
    }
    return frame;
}

} // namespace trimlab
