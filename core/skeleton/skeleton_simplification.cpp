#include "core/skeleton/skeleton_simplification.h"

#include "core/skeleton/collapse_complex.h"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include <cstdint>
#include <limits>
#include <queue>

namespace trimlab {

namespace {

// Q_i of eq. (7): Σ K_ijᵀK_ij over the edges (i, j), a symmetric 4×4 matrix.
using Quadric = glm::dmat4;

// K_ijᵀK_ij for the line through `from` along `to` − `from` (eq. 6): K·[p; 1] = a×p − b
// with a the unit edge direction and b = a×v_i, whose norm is p's distance to the line.
Quadric edgeQuadric(const glm::dvec3& from, const glm::dvec3& to)
{
    const double length = glm::length(to - from);
    if (!(length > 0.0))
        return Quadric(0.0); // a zero-length edge has no direction: no constraint
    const glm::dvec3 a = (to - from) / length;
    const glm::dvec3 b = glm::cross(a, from);
    const glm::dvec4 rows[3] = {glm::dvec4(0.0, -a.z, a.y, -b.x), glm::dvec4(a.z, 0.0, -a.x, -b.y),
                                glm::dvec4(-a.y, a.x, 0.0, -b.z)};
    Quadric q(0.0);
    for (const glm::dvec4& r : rows)
        for (int c = 0; c < 4; ++c)
            q[c] += r[c] * r; // column c of rᵀr
    return q;
}

double quadricValue(const Quadric& q, const glm::dvec3& p)
{
    const glm::dvec4 h(p, 1.0);
    return glm::dot(h, q * h);
}

struct Candidate {
    double cost;
    int from, to;
    std::uint32_t fromStamp, toStamp;
    bool operator>(const Candidate& other) const { return cost > other.cost; }
};
using CandidateQueue = std::priority_queue<Candidate, std::vector<Candidate>, std::greater<>>;

class Simplifier {
public:
    Simplifier(std::span<const glm::dvec3> contracted, std::span<const glm::uvec3> triangles,
               const SimplificationOptions& options, const TaskControl& control)
        : m_complex(contracted, triangles),
          m_quadrics(contracted.size(), Quadric(0.0)),
          m_stamps(contracted.size(), 0),
          m_referenced(contracted.size(), 0),
          m_options(options),
          m_control(control)
    {
        for (const glm::uvec3& t : triangles)
            for (int c = 0; c < 3; ++c) {
                m_referenced[t[c]] = 1;
                // Each undirected edge appears in two triangles; each adds half per endpoint.
                const glm::dvec3 &p = contracted[t[c]], &q = contracted[t[(c + 1) % 3]];
                m_quadrics[t[c]] += 0.5 * edgeQuadric(p, q);
                m_quadrics[t[(c + 1) % 3]] += 0.5 * edgeQuadric(q, p);
            }
        m_total = contracted.size() > 0 ? contracted.size() - 1 : 0;
    }

    void preCollapse(double delta);
    void collapseToCurve();
    CurveSkeleton result();

private:
    double cost(int from, int to) const;
    void updateAround(int v);
    void push(int u, int w);
    void rebuildQueue();
    void merge(int from, int to);

    CollapseComplex m_complex;
    std::vector<Quadric> m_quadrics;
    std::vector<std::uint32_t> m_stamps;
    std::vector<char> m_referenced; // used by a triangle of the input
    std::vector<double> m_around;   // Σ_k |v_i − v_k| over the current edges of i (F_b's sum)
    CandidateQueue m_queue;
    std::size_t m_pushesSinceRebuild = 0, m_sizeAtRebuild = 0;
    SimplificationOptions m_options;
    const TaskControl& m_control;
    std::size_t m_collapses = 0, m_total = 0;
};

double Simplifier::cost(int from, int to) const
{
    const glm::dvec3& vi = m_complex.position(from);
    const glm::dvec3& vj = m_complex.position(to);
    const double shape =
        quadricValue(m_quadrics[static_cast<std::size_t>(from)] + m_quadrics[static_cast<std::size_t>(to)], vj);
    const double sampling = glm::length(vi - vj) * m_around[static_cast<std::size_t>(from)];
    return m_options.shapeWeight * shape + m_options.samplingWeight * sampling;
}

void Simplifier::updateAround(int v)
{
    double sum = 0.0;
    for (int k : m_complex.neighbours(v))
        sum += glm::length(m_complex.position(v) - m_complex.position(k));
    m_around[static_cast<std::size_t>(v)] = sum;
}

void Simplifier::push(int u, int w)
{
    const double uw = cost(u, w), wu = cost(w, u);
    const auto su = m_stamps[static_cast<std::size_t>(u)], sw = m_stamps[static_cast<std::size_t>(w)];
    if (uw <= wu)
        m_queue.push({uw, u, w, su, sw});
    else
        m_queue.push({wu, w, u, sw, su});
    ++m_pushesSinceRebuild;
}

// Lazy invalidation leaves stale entries behind; once they outnumber the live ones
// several times over, start afresh so memory stays proportional to the edges.
void Simplifier::rebuildQueue()
{
    m_queue = CandidateQueue();
    for (int v = 0; v < static_cast<int>(m_complex.vertexCount()); ++v)
        if (m_complex.alive(v))
            for (int w : m_complex.neighbours(v))
                if (v < w && m_complex.edgeHasTriangle(v, w))
                    push(v, w);
    m_sizeAtRebuild = m_queue.size();
    m_pushesSinceRebuild = 0;
}

void Simplifier::merge(int from, int to)
{
    m_complex.collapse(from, to);
    m_quadrics[static_cast<std::size_t>(to)] += m_quadrics[static_cast<std::size_t>(from)];
    if (++m_collapses % 1024 == 0) {
        m_control.throwIfCancelled();
        m_control.report("simplification", m_collapses, m_total);
    }
}

void Simplifier::preCollapse(double delta)
{
    if (!(delta > 0.0))
        return;
    using Short = std::pair<double, std::pair<int, int>>;
    std::priority_queue<Short, std::vector<Short>, std::greater<>> queue;
    const auto pushShort = [&](int a, int b) {
        const double length = glm::length(m_complex.position(a) - m_complex.position(b));
        if (length <= delta)
            queue.push({length, {a, b}});
    };
    for (int v = 0; v < static_cast<int>(m_complex.vertexCount()); ++v)
        for (int w : m_complex.neighbours(v))
            if (v < w)
                pushShort(v, w);
    while (!queue.empty()) {
        const auto [a, b] = queue.top().second;
        queue.pop();
        // Positions never move, so an entry whose ends both live still has its length.
        if (!m_complex.alive(a) || !m_complex.alive(b) || !m_complex.edgeHasTriangle(a, b))
            continue;
        merge(a, b);
        for (int k : m_complex.neighbours(b))
            pushShort(b, k);
    }
}

void Simplifier::collapseToCurve()
{
    m_around.assign(m_complex.vertexCount(), 0.0);
    for (int v = 0; v < static_cast<int>(m_complex.vertexCount()); ++v)
        if (m_complex.alive(v))
            updateAround(v);
    rebuildQueue();
    std::vector<int> formerNeighbours;
    while (m_complex.liveTriangleCount() > 0) {
        if (m_queue.empty()) {
            rebuildQueue();
            if (m_queue.empty())
                break; // unreachable: every live triangle has three collapsible edges
        }
        const Candidate c = m_queue.top();
        m_queue.pop();
        if (!m_complex.alive(c.from) || !m_complex.alive(c.to) ||
            m_stamps[static_cast<std::size_t>(c.from)] != c.fromStamp ||
            m_stamps[static_cast<std::size_t>(c.to)] != c.toStamp || !m_complex.edgeHasTriangle(c.from, c.to))
            continue;
        formerNeighbours = m_complex.neighbours(c.from);
        merge(c.from, c.to);
        // Changed: Q_to and the edges of `to`, and the edges of every former neighbour k of
        // `from` (its edge to `from` became one to `to`, or merged with it), hence their F_b
        // sums. Every edge touching one of them gets a new cost; the other neighbours of
        // `to` kept their edges, and their edge to `to` is re-pushed with `to`'s.
        ++m_stamps[static_cast<std::size_t>(c.to)];
        updateAround(c.to);
        for (int k : formerNeighbours)
            if (k != c.to) {
                ++m_stamps[static_cast<std::size_t>(k)];
                updateAround(k);
            }
        for (int w : m_complex.neighbours(c.to))
            if (m_complex.edgeHasTriangle(c.to, w))
                push(c.to, w);
        for (int k : formerNeighbours)
            if (k != c.to)
                for (int w : m_complex.neighbours(k))
                    if (w != c.to && m_complex.edgeHasTriangle(k, w))
                        push(k, w);
        if (m_pushesSinceRebuild > 3 * m_sizeAtRebuild + 4096)
            rebuildQueue();
    }
}

CurveSkeleton Simplifier::result()
{
    CurveSkeleton curve;
    const int n = static_cast<int>(m_complex.vertexCount());
    std::vector<int> nodeOf(static_cast<std::size_t>(n), -1);
    for (int v = 0; v < n; ++v) {
        if (!m_complex.alive(v) || !m_referenced[static_cast<std::size_t>(v)])
            continue;
        nodeOf[static_cast<std::size_t>(v)] = static_cast<int>(curve.nodes.size());
        curve.nodes.push_back(m_complex.position(v));
    }
    for (int v = 0; v < n; ++v)
        if (nodeOf[static_cast<std::size_t>(v)] >= 0)
            for (int w : m_complex.neighbours(v))
                if (v < w && nodeOf[static_cast<std::size_t>(w)] >= 0)
                    curve.edges.push_back({nodeOf[static_cast<std::size_t>(v)], nodeOf[static_cast<std::size_t>(w)]});
    std::sort(curve.edges.begin(), curve.edges.end());
    curve.vertexNode.resize(static_cast<std::size_t>(n), -1);
    for (int v = 0; v < n; ++v) {
        if (m_referenced[static_cast<std::size_t>(v)]) {
            curve.vertexNode[static_cast<std::size_t>(v)] =
                nodeOf[static_cast<std::size_t>(m_complex.representative(v))];
            continue;
        }
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < curve.nodes.size(); ++k)
            if (const double d = glm::length(curve.nodes[k] - m_complex.position(v)); d < best) {
                best = d;
                curve.vertexNode[static_cast<std::size_t>(v)] = static_cast<int>(k);
            }
    }
    return curve;
}

} // namespace

CurveSkeleton simplifyContractedMesh(std::span<const glm::dvec3> contracted, std::span<const glm::uvec3> triangles,
                                     double delta, const SimplificationOptions& options, const TaskControl& control)
{
    Simplifier simplifier(contracted, triangles, options, control);
    control.report("simplification", 0, contracted.empty() ? 0 : contracted.size() - 1);
    simplifier.preCollapse(delta);
    simplifier.collapseToCurve();
    CurveSkeleton curve = simplifier.result();
    control.report("simplification", contracted.empty() ? 0 : contracted.size() - 1,
                   contracted.empty() ? 0 : contracted.size() - 1);
    return curve;
}

} // namespace trimlab
