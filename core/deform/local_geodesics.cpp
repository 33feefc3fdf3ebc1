#include "core/deform/local_geodesics.h"

#include "core/deform/local_vertex_map.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <stdexcept>
#include <utility>

namespace trimlab::deform {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kReopenMargin = 1e-12;

// The front of the local Dijkstra. State lives in a hash map keyed by vertex so that a
// stroke on a 100k-vertex mesh touches only the few thousand vertices near the anchor;
// the map is only looked up, never iterated, so its layout cannot leak into the result.
class Front {
public:
    Front(const BrushTopology& topology, std::span<const glm::vec3> positions, double radius)
        : m_topology(topology), m_positions(positions), m_radius(radius)
    {
    }

    void offer(std::uint32_t v, double candidate);
    void run();
    [[nodiscard]] LocalDistances result() const;

private:
    struct Node {
        double distance = kInfinity;
        bool settled = false;
    };
    using Entry = std::pair<double, std::uint32_t>; // (distance, vertex): ties by index

    void relaxEdges(std::uint32_t v, double d);
    void relaxTriangles(std::uint32_t v, double d);
    [[nodiscard]] const Node* find(std::uint32_t v) const;
    [[nodiscard]] glm::dvec3 position(std::uint32_t v) const { return glm::dvec3(m_positions[v]); }

    const BrushTopology& m_topology;
    std::span<const glm::vec3> m_positions;
    double m_radius;
    LocalVertexMap<Node> m_nodes;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> m_queue;
    std::vector<std::uint32_t> m_settled; // every settling, in order (reopened ones repeat)
};

const Front::Node* Front::find(std::uint32_t v) const
{
    return m_nodes.find(v);
}

// A settled vertex is reopened when a triangle update finds it shorter by more than
// rounding: across right and obtuse triangles the line from the source to c can enter
// through an edge whose far corner is farther than c, so c's best value only appears
// after c was settled from edges alone. The relative margin stops rounding-level
// improvements from bouncing between vertices forever.
void Front::offer(std::uint32_t v, double candidate)
{
    if (!(candidate < m_radius))
        return;
    Node& node = m_nodes[v];
    if (!(candidate < node.distance * (1.0 - kReopenMargin))) // inf stays inf
        return;
    node.distance = candidate;
    node.settled = false;
    m_queue.emplace(candidate, v);
}

void Front::run()
{
    while (!m_queue.empty()) {
        const auto [d, v] = m_queue.top();
        m_queue.pop();
        Node& node = m_nodes[v];
        if (node.settled || d != node.distance)
            continue; // a stale entry, superseded by a shorter one
        node.settled = true;
        m_settled.push_back(v);
        relaxEdges(v, d);
        relaxTriangles(v, d);
    }
}

void Front::relaxEdges(std::uint32_t v, double d)
{
    const glm::dvec3 p = position(v);
    for (const std::uint32_t* u = m_topology.ringBegin(v); u != m_topology.ringEnd(v); ++u)
        offer(*u, d + glm::distance(p, position(*u)));
}

// For each triangle (v, o, w) with o settled: the unfolded point-source update of w from
// the pair (v, o), which may reopen w (see offer).
void Front::relaxTriangles(std::uint32_t v, double d)
{
    const auto& triangles = m_topology.triangles();
    for (const std::uint32_t* f = m_topology.facesBegin(v); f != m_topology.facesEnd(v); ++f) {
        const glm::uvec3& t = triangles[*f];
        const int corner = t.x == v ? 0 : (t.y == v ? 1 : 2);
        const std::uint32_t others[2] = {t[(corner + 1) % 3], t[(corner + 2) % 3]};
        if (others[0] == v || others[1] == v || others[0] == others[1])
            continue; // degenerate index triple
        for (int i = 0; i < 2; ++i) {
            const std::uint32_t o = others[i], w = others[1 - i];
            const Node* known = find(o);
            if (known == nullptr || !known->settled)
                continue;
            const double candidate = unfoldedDistance(position(v), position(o), position(w), d, known->distance);
            if (candidate < kInfinity)
                offer(w, candidate);
        }
    }
}

LocalDistances Front::result() const
{
    LocalDistances out;
    out.vertices = m_settled;
    std::sort(out.vertices.begin(), out.vertices.end());
    out.vertices.erase(std::unique(out.vertices.begin(), out.vertices.end()), out.vertices.end());
    out.distances.reserve(out.vertices.size());
    for (std::uint32_t v : out.vertices)
        out.distances.push_back(find(v)->distance);
    return out;
}

} // namespace

double unfoldedDistance(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, double da, double db)
{
    // Frame in the triangle's plane: a at the origin, b on +x at (L, 0), c at (cx, cy > 0).
    const double L = glm::distance(a, b);
    if (!(L > 0.0))
        return kInfinity;
    const glm::dvec3 e = (b - a) / L;
    const glm::dvec3 ac = c - a;
    const double cx = glm::dot(ac, e);
    const double cy = glm::length(ac - cx * e);
    if (!(cy > 0.0))
        return kInfinity;

    // The source s = (sx, sy) with |s − a| = da, |s − b| = db, below the x axis.
    const double sx = (da * da - db * db + L * L) / (2.0 * L);
    double sy2 = da * da - sx * sx;
    const double scale2 = std::max({da * da, db * db, L * L});
    if (sy2 < 0.0 && sy2 > -1e-12 * scale2)
        sy2 = 0.0; // a source on the line ab, up to rounding
    if (!(sy2 >= 0.0))
        return kInfinity;
    const double sy = -std::sqrt(sy2);

    // Where the segment s → c crosses y = 0; valid only through the edge ab itself.
    const double x = sx + (cx - sx) * (-sy / (cy - sy));
    if (x < 0.0 || x > L)
        return kInfinity;
    return std::hypot(cx - sx, cy - sy);
}

LocalDistances localGeodesicDistances(const BrushTopology& topology, std::span<const glm::vec3> positions,
                                      std::span<const GeodesicSeed> seeds, double radius)
{
    if (positions.size() != topology.vertexCount())
        throw std::invalid_argument("localGeodesicDistances: positions do not match the topology");
    Front front(topology, positions, radius);
    for (const GeodesicSeed& seed : seeds) {
        if (seed.vertex >= topology.vertexCount())
            throw std::invalid_argument("localGeodesicDistances: seed vertex out of range");
        front.offer(seed.vertex, std::max(seed.distance, 0.0));
    }
    front.run();
    return front.result();
}

} // namespace trimlab::deform
