#include "core/timeline/timeline.h"

#include "core/util/float_bits.h"
#include "core/timeline/stroke_validation.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace trimlab::timeline {

namespace {

std::string vec3Text(const glm::vec3& p)
{
    return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " + std::to_string(p.z) + ")";
}

bool isFinite(const glm::vec3& p)
{
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// The vertex list of a frame: sorted, unique, in range, and matching the position arrays.
void checkVertexList(const Frame& frame, std::size_t vertexCount)
{
    if (frame.before.size() != frame.vertices.size() || frame.after.size() != frame.vertices.size())
        throw std::invalid_argument("the frame lists " + std::to_string(frame.vertices.size()) + " vertices but " +
                                    std::to_string(frame.before.size()) + " 'before' and " +
                                    std::to_string(frame.after.size()) + " 'after' positions");
    for (std::size_t i = 0; i < frame.vertices.size(); ++i) {
        const std::uint32_t v = frame.vertices[i];
        if (v >= vertexCount)
            throw std::invalid_argument("vertex " + std::to_string(v) + " is out of range (the mesh has " +
                                        std::to_string(vertexCount) + " vertices)");
        if (i > 0 && v <= frame.vertices[i - 1])
            throw std::invalid_argument("the vertices are not sorted ascending and unique: " +
                                        std::to_string(frame.vertices[i - 1]) + " is followed by " + std::to_string(v));
    }
}

void checkTriangles(const TriangleMesh& mesh)
{
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const glm::uvec3& tri = mesh.triangles[t];
        for (int c = 0; c < 3; ++c) {
            if (tri[c] >= mesh.positions.size())
                throw std::invalid_argument("base triangle " + std::to_string(t) + " references vertex " +
                                            std::to_string(tri[c]) + ", but the mesh has only " +
                                            std::to_string(mesh.positions.size()) + " vertices");
        }
    }
}

void checkSets(const std::vector<DeformationSet>& sets, std::size_t frameTotal)
{
    if (sets.empty() && frameTotal == 0)
        return; // a default-constructed timeline: nothing to group
    if (sets.empty())
        throw std::invalid_argument("a timeline with frames needs at least one set");
    long long expectedFirst = 1;
    for (std::size_t s = 0; s < sets.size(); ++s) {
        const std::string where = "sets[" + std::to_string(s) + "]: ";
        if (sets[s].firstFrame != expectedFirst)
            throw std::invalid_argument(where + "starts at frame " + std::to_string(sets[s].firstFrame) +
                                        ", expected " + std::to_string(expectedFirst));
        if (sets[s].frameCount < 0)
            throw std::invalid_argument(where + "has a negative frame count " + std::to_string(sets[s].frameCount));
        expectedFirst += sets[s].frameCount;
    }
    if (expectedFirst - 1 != static_cast<long long>(frameTotal))
        throw std::invalid_argument("the sets hold " + std::to_string(expectedFirst - 1) + " frames but there are " +
                                    std::to_string(frameTotal));
}

std::string dvec3Text(const glm::dvec3& p)
{
    return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " + std::to_string(p.z) + ")";
}

// Tied NURBS points (seam twins, poles) must end where their partners end.
void checkTies(const SurfaceDefinition& surface, const std::vector<glm::dvec3>& current,
               const std::vector<ControlPointMove>& moves)
{
    if (surface.kind() != SurfaceKind::Nurbs)
        return;
    std::vector<glm::dvec3> next = current;
    for (const ControlPointMove& move : moves)
        next[move.index] = move.after;
    for (std::size_t k = 0; k < moves.size(); ++k) {
        for (const std::uint32_t tied : tiedControlPoints(surface, moves[k].index)) {
            if (!sameBits(next[tied], moves[k].after))
                throw std::invalid_argument("control move " + std::to_string(k) + ": control point " +
                                            std::to_string(moves[k].index) + " is tied to control point " +
                                            std::to_string(tied) +
                                            " (a seam twin or the same pole), which must move with it");
        }
    }
}

} // namespace

Timeline::Timeline(TriangleMesh base, DynamicRule firstRule)
    : m_base(std::move(base)), m_sets{DeformationSet{firstRule, 1, 0}}
{
    m_current = m_base.positions;
}

Timeline::Timeline(TriangleMesh base, SurfaceDefinition surface, DynamicRule firstRule)
    : Timeline(std::move(base), firstRule)
{
    requireValidSurfaceDefinition(surface, "Timeline");
    m_currentControl = surface.controlPoints();
    m_surface = std::move(surface);
}

Timeline Timeline::restore(TriangleMesh base, std::vector<Frame> frames, std::vector<DeformationSet> sets,
                           std::optional<SurfaceDefinition> surface)
{
    checkTriangles(base);
    checkSets(sets, frames.size());
    Timeline timeline = surface ? Timeline(std::move(base), std::move(*surface)) : Timeline(std::move(base));
    timeline.m_frames.reserve(frames.size());
    for (std::size_t f = 0; f < frames.size(); ++f) {
        try {
            timeline.appendFrame(std::move(frames[f]));
        } catch (const std::invalid_argument& error) {
            throw std::invalid_argument("frames[" + std::to_string(f) + "]: " + error.what());
        }
    }
    timeline.m_sets = std::move(sets);
    return timeline;
}

const Frame& Timeline::frame(int f) const
{
    if (f < 1 || f >= frameCount())
        throw std::out_of_range("Timeline::frame: frame " + std::to_string(f) + " does not exist (frames 1 to " +
                                std::to_string(frameCount() - 1) + " hold strokes)");
    return m_frames[std::size_t(f - 1)];
}

int Timeline::setOfFrame(int f) const
{
    if (f < 0 || f >= frameCount())
        throw std::out_of_range("Timeline::setOfFrame: frame " + std::to_string(f) +
                                " does not exist (the timeline has " + std::to_string(frameCount()) + " frames)");
    for (std::size_t s = 0; s < m_sets.size(); ++s) {
        const DeformationSet& set = m_sets[s];
        if (f >= set.firstFrame && f < set.firstFrame + set.frameCount)
            return int(s);
    }
    return 0; // frame 0, the base mesh
}

std::vector<glm::vec3> Timeline::positionsAt(int f) const
{
    if (f < 0 || f >= frameCount())
        throw std::out_of_range("Timeline::positionsAt: frame " + std::to_string(f) +
                                " does not exist (the timeline has " + std::to_string(frameCount()) + " frames)");
    if (f == frameCount() - 1)
        return m_current;
    std::vector<glm::vec3> positions = m_base.positions;
    for (int i = 0; i < f; ++i) {
        const Frame& frame = m_frames[std::size_t(i)];
        for (std::size_t k = 0; k < frame.vertices.size(); ++k)
            positions[frame.vertices[k]] = frame.after[k];
    }
    return positions;
}

std::vector<glm::dvec3> Timeline::controlPointsAt(int f) const
{
    if (f < 0 || f >= frameCount())
        throw std::out_of_range("Timeline::controlPointsAt: frame " + std::to_string(f) +
                                " does not exist (the timeline has " + std::to_string(frameCount()) + " frames)");
    if (f == frameCount() - 1 || !m_surface)
        return m_currentControl;
    std::vector<glm::dvec3> points = m_surface->controlPoints();
    for (int i = 0; i < f; ++i)
        for (const ControlPointMove& move : m_frames[std::size_t(i)].controlMoves)
            points[move.index] = move.after;
    return points;
}

TriangleMesh Timeline::meshAt(int f) const
{
    return TriangleMesh{positionsAt(f), m_base.triangles};
}

void Timeline::checkControlMoves(const Frame& frame) const
{
    if (!m_surface)
        throw std::invalid_argument("a control-point edit needs a surface definition (this history has none)");
    const std::vector<ControlPointMove>& moves = frame.controlMoves;
    for (std::size_t k = 0; k < moves.size(); ++k) {
        const std::string where = "control move " + std::to_string(k) + ": ";
        const ControlPointMove& move = moves[k];
        if (move.index >= m_currentControl.size())
            throw std::invalid_argument(where + "control point " + std::to_string(move.index) +
                                        " is out of range (the surface has " + std::to_string(m_currentControl.size()) +
                                        " control points)");
        if (k > 0 && move.index <= moves[k - 1].index)
            throw std::invalid_argument(where + "the control points are not sorted ascending and unique: " +
                                        std::to_string(moves[k - 1].index) + " is followed by " +
                                        std::to_string(move.index));
        if (!sameBits(move.before, m_currentControl[move.index]))
            throw std::invalid_argument(where + "the 'before' position " + dvec3Text(move.before) +
                                        " of control point " + std::to_string(move.index) +
                                        " differs from its current position " +
                                        dvec3Text(m_currentControl[move.index]));
        if (!std::isfinite(move.after.x) || !std::isfinite(move.after.y) || !std::isfinite(move.after.z))
            throw std::invalid_argument(where + "the 'after' position of control point " + std::to_string(move.index) +
                                        " is not finite");
    }
    checkTies(*m_surface, m_currentControl, moves);
}

void Timeline::checkFrame(const Frame& frame) const
{
    if (frame.isControlEdit())
        checkControlMoves(frame);
    else if (m_surface)
        throw std::invalid_argument("this history edits a " + std::string(surfaceKindName(m_surface->kind())) +
                                    " surface through its control points; a brush stroke on its mesh would "
                                    "break that (use the control-point brush)");
    else if (const std::string problem = strokeProblem(frame.stroke); !problem.empty())
        throw std::invalid_argument("invalid stroke: " + problem);
    checkVertexList(frame, m_current.size());
    for (std::size_t k = 0; k < frame.vertices.size(); ++k) {
        const std::uint32_t v = frame.vertices[k];
        // Bit equality: the history must reproduce positions exactly, -0.0f included.
        if (!sameBits(frame.before[k], m_current[v]))
            throw std::invalid_argument("the 'before' position " + vec3Text(frame.before[k]) + " of vertex " +
                                        std::to_string(v) + " differs from its current position " +
                                        vec3Text(m_current[v]));
        if (!isFinite(frame.after[k]))
            throw std::invalid_argument("the 'after' position of vertex " + std::to_string(v) + " is not finite");
    }
}

void Timeline::appendFrame(Frame frame)
{
    checkFrame(frame);
    for (std::size_t k = 0; k < frame.vertices.size(); ++k)
        m_current[frame.vertices[k]] = frame.after[k];
    for (const ControlPointMove& move : frame.controlMoves)
        m_currentControl[move.index] = move.after;
    if (m_sets.empty())
        m_sets.push_back(DeformationSet{DynamicRule::Confluent, frameCount(), 0});
    ++m_sets.back().frameCount;
    m_frames.push_back(std::move(frame));
}

Frame Timeline::removeLastFrame()
{
    if (m_frames.empty())
        throw std::logic_error("Timeline::removeLastFrame: the timeline has no strokes to remove");
    Frame frame = std::move(m_frames.back());
    m_frames.pop_back();
    for (std::size_t k = 0; k < frame.vertices.size(); ++k)
        m_current[frame.vertices[k]] = frame.before[k];
    for (const ControlPointMove& move : frame.controlMoves)
        m_currentControl[move.index] = move.before;
    std::size_t owner = m_sets.size() - 1;
    while (m_sets[owner].frameCount == 0)
        --owner; // the sets hold every frame, so a non-empty one exists
    --m_sets[owner].frameCount;
    // Empty sets after it now start from the new last frame.
    for (std::size_t s = owner + 1; s < m_sets.size(); ++s)
        m_sets[s].firstFrame = frameCount();
    return frame;
}

void Timeline::startSet(DynamicRule rule)
{
    if (!m_sets.empty() && m_sets.back().frameCount == 0) {
        m_sets.back().rule = rule;
        return;
    }
    m_sets.push_back(DeformationSet{rule, frameCount(), 0});
}

void Timeline::removeLastSetIfEmpty()
{
    if (m_sets.size() > 1 && m_sets.back().frameCount == 0)
        m_sets.pop_back();
}

void Timeline::setRule(int s, DynamicRule rule)
{
    if (s < 0 || std::size_t(s) >= m_sets.size())
        throw std::out_of_range("Timeline::setRule: set " + std::to_string(s) + " does not exist (the timeline has " +
                                std::to_string(m_sets.size()) + " sets)");
    m_sets[std::size_t(s)].rule = rule;
}

std::vector<Timeline::ChainLink> Timeline::chainTo(int f) const
{
    const int last = setOfFrame(f);
    std::vector<ChainLink> chain;
    for (int s = 0; s <= last && std::size_t(s) < m_sets.size(); ++s)
        chain.push_back(ChainLink{m_sets[std::size_t(s)].referenceFrame(), m_sets[std::size_t(s)].rule});
    return chain;
}

} // namespace trimlab::timeline
