#include "core/skeleton/bone_heat_terms.h"

#include "core/util/parallel_for.h"
#include "core/scene/scene.h"
#include "core/trim/ray_hit.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

namespace trimlab {

namespace {

Scene singleObjectScene(const TriangleMesh& mesh)
{
    Scene scene;
    scene.objects.push_back({"mesh", mesh, glm::dmat4(1.0)});
    return scene;
}

bool isFinite(const glm::dvec3& p)
{
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

void requireUsableRig(const SkeletonRig& rig)
{
    if (rig.bones.empty())
        throw std::invalid_argument("bone heat: the rig has no bones (it needs at least two joints)");
    for (std::size_t b = 0; b < rig.bones.size(); ++b) {
        const Bone& bone = rig.bones[b];
        for (const int joint : {bone.head, bone.tail})
            if (joint < 0 || std::size_t(joint) >= rig.joints.size())
                throw std::invalid_argument("bone heat: bone " + std::to_string(b) + " names joint " +
                                            std::to_string(joint) + " of " + std::to_string(rig.joints.size()));
    }
    for (std::size_t j = 0; j < rig.joints.size(); ++j)
        if (!isFinite(rig.joints[j]))
            throw std::invalid_argument("bone heat: joint " + std::to_string(j) + " is not finite");
}

// The nearest bones of one vertex and their closest points; `distances` and `candidates`
// are scratch space reused between the vertices of one block.
struct NearestBones {
    std::vector<int> bones;
    std::vector<glm::dvec3> points;
    double distance = 0.0;
};

struct NearestScratch {
    std::vector<double> distances;
    std::vector<glm::dvec3> candidates;
};

// Every bone's closest point to p and its distance.
void boneDistances(const glm::dvec3& p, const SkeletonRig& rig, NearestScratch& scratch)
{
    scratch.distances.resize(rig.bones.size());
    scratch.candidates.resize(rig.bones.size());
    for (std::size_t b = 0; b < rig.bones.size(); ++b) {
        const Bone& bone = rig.bones[b];
        scratch.candidates[b] =
            closestPointOnSegment(p, rig.joints[std::size_t(bone.head)], rig.joints[std::size_t(bone.tail)]);
        scratch.distances[b] = glm::length(p - scratch.candidates[b]);
    }
}

// The nearest group of equidistant bones (within the tolerance of the nearest, ascending
// bone index) among those farther than `beyond`; false when none is. One pass over the
// bones: most vertices see their nearest group, so the others are rarely asked for.
bool tiedGroup(const NearestScratch& scratch, double beyond, double tolerance, NearestBones& out)
{
    out.bones.clear();
    out.points.clear();
    double best = std::numeric_limits<double>::infinity();
    for (const double d : scratch.distances)
        if (d > beyond)
            best = std::min(best, d);
    if (!std::isfinite(best))
        return false;
    for (std::size_t b = 0; b < scratch.distances.size(); ++b)
        if (scratch.distances[b] > beyond && scratch.distances[b] <= best * (1.0 + tolerance)) {
            out.bones.push_back(int(b));
            out.points.push_back(scratch.candidates[b]);
        }
    out.distance = best;
    return true;
}

// Per vertex: which nearest bones, which of them visible.
struct VertexResult {
    NearestBones nearest;
    std::vector<std::uint8_t> visible;
};

// The nearest bones of p that it sees: the nearest group of equidistant bones of which at
// least one is visible, as Pinocchio heats a vertex from its nearest visible bone. A bone
// that is nearer but hidden (an arm hanging beside the body, seen across the gap) heats
// nothing. When no bone is visible, the nearest group with nothing visible.
VertexResult nearestVisibleBones(const glm::dvec3& p, const SkeletonRig& rig, double tolerance,
                                 const SegmentVisibility* visibility, NearestScratch& scratch,
                                 std::vector<RayHit>& hits)
{
    VertexResult r;
    if (!isFinite(p)) { // no distance: bone 0 stands in, never visible, no heat
        r.nearest.bones.push_back(0);
        r.nearest.points.push_back(rig.joints[std::size_t(rig.bones[0].head)]);
        r.nearest.distance = std::numeric_limits<double>::infinity();
        r.visible.push_back(0);
        return r;
    }
    boneDistances(p, rig, scratch);
    NearestBones group;
    for (double beyond = -1.0; tiedGroup(scratch, beyond, tolerance, group);
         beyond = group.distance * (1.0 + tolerance)) {
        std::vector<std::uint8_t> seen(group.bones.size(), 0);
        for (std::size_t i = 0; i < group.bones.size(); ++i)
            seen[i] = !visibility || visibility->inside(p, group.points[i], hits) ? 1 : 0;
        const bool nearest = beyond < 0.0;
        if (nearest) { // kept when no group is visible
            r.nearest = group;
            r.visible = seen;
        }
        if (std::find(seen.begin(), seen.end(), std::uint8_t(1)) != seen.end()) {
            r.nearest = std::move(group);
            r.visible = std::move(seen);
            break;
        }
    }
    return r;
}

double sceneSize(const TriangleMesh& mesh, const SkeletonRig& rig)
{
    Bounds bounds = computeBounds(mesh);
    for (const glm::dvec3& j : rig.joints)
        bounds.extend(j);
    return bounds.valid() ? glm::length(bounds.max - bounds.min) : 1.0;
}

// Fills the CSR arrays and H from the per-vertex results.
BoneHeatTerms assembleTerms(const std::vector<VertexResult>& results, double heatConstant, double distanceFloor)
{
    BoneHeatTerms terms;
    terms.heat.resize(results.size());
    terms.distance.resize(results.size());
    terms.nearestOffsets.reserve(results.size() + 1);
    terms.nearestOffsets.push_back(0);
    for (std::size_t j = 0; j < results.size(); ++j) {
        const VertexResult& r = results[j];
        terms.nearestBones.insert(terms.nearestBones.end(), r.nearest.bones.begin(), r.nearest.bones.end());
        terms.visible.insert(terms.visible.end(), r.visible.begin(), r.visible.end());
        terms.nearestOffsets.push_back(std::uint32_t(terms.nearestBones.size()));
        const double d = std::max(r.nearest.distance, distanceFloor);
        terms.distance[j] = d;
        const auto k = double(std::count(r.visible.begin(), r.visible.end(), std::uint8_t(1)));
        terms.heat[j] = std::isfinite(d) ? k * heatConstant / (d * d) : 0.0;
        terms.hiddenVertices += terms.heat[j] > 0.0 ? 0 : 1;
    }
    return terms;
}

} // namespace

glm::dvec3 closestPointOnSegment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b)
{
    const glm::dvec3 ab = b - a;
    const double length2 = glm::dot(ab, ab);
    if (!(length2 > 0.0))
        return a;
    const double t = std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0);
    return a + t * ab;
}

SegmentVisibility::SegmentVisibility(const TriangleMesh& mesh) : m_bvh(singleObjectScene(mesh))
{
    const Bounds bounds = computeBounds(mesh);
    if (bounds.valid()) {
        m_center = bounds.center();
        m_radius = bounds.radius();
    }
}

bool SegmentVisibility::inside(const glm::dvec3& from, const glm::dvec3& to, std::vector<RayHit>& hits) const
{
    const glm::dvec3 direction = to - from;
    const double length = glm::length(direction);
    if (!isFinite(from) || !isFinite(to))
        return false;
    if (!(length > 1e-12 * std::max(m_radius, std::numeric_limits<double>::min())))
        return true;
    // Beyond the bounding sphere the ray meets nothing: stop the query there.
    const double tEnd = 1.0 + (glm::length(from - m_center) + 2.0 * m_radius) / length;
    hits.clear();
    m_bvh.intersectAll(PixelRay{from, direction}, kSegmentEpsilon, tEnd, hits);
    std::sort(hits.begin(), hits.end(), walkOrder);
    // Beyond the last hit w = 0; crossing a hit changes w by its facing, so just past ε
    // w = −Σ facing. Walk the segment and require w ≠ 0 on every piece of it.
    int w = 0;
    for (const RayHit& hit : hits)
        w -= hit.facing;
    double previous = -1.0;
    for (const RayHit& hit : hits) {
        if (hit.t > 1.0 - kSegmentEpsilon)
            break;
        if (hit.t > previous && w == 0) // the piece before this hit (hits at one t: one crossing point)
            return false;
        previous = hit.t;
        w += hit.facing;
    }
    return w != 0;
}

std::span<const int> BoneHeatTerms::nearest(std::size_t vertex) const
{
    return std::span<const int>(nearestBones)
        .subspan(nearestOffsets[vertex], nearestOffsets[vertex + 1] - nearestOffsets[vertex]);
}

std::size_t BoneHeatTerms::visibleCount(std::size_t vertex) const
{
    return std::size_t(std::count(visible.begin() + nearestOffsets[vertex],
                                  visible.begin() + nearestOffsets[vertex + 1], std::uint8_t(1)));
}

double BoneHeatTerms::source(std::size_t vertex, int bone) const
{
    const std::size_t k = visibleCount(vertex);
    for (std::uint32_t e = nearestOffsets[vertex]; e < nearestOffsets[vertex + 1]; ++e)
        if (nearestBones[e] == bone && visible[e])
            return 1.0 / double(k);
    return 0.0;
}

BoneHeatTerms boneHeatTerms(const TriangleMesh& mesh, const SkeletonRig& rig, const BoneHeatTermOptions& options,
                            const TaskControl& control)
{
    requireUsableRig(rig);
    if (!(options.heatConstant > 0.0) || !std::isfinite(options.heatConstant))
        throw std::invalid_argument("bone heat: the heat constant c must be finite and > 0, not " +
                                    std::to_string(options.heatConstant));
    if (!(options.tieTolerance >= 0.0) || !std::isfinite(options.tieTolerance))
        throw std::invalid_argument("bone heat: the tie tolerance must be finite and ≥ 0, not " +
                                    std::to_string(options.tieTolerance));
    std::optional<SegmentVisibility> visibility;
    if (options.visibility)
        visibility.emplace(mesh);
    std::vector<VertexResult> results(mesh.vertexCount());
    constexpr std::size_t kBlock = 512;
    const std::size_t blocks = (results.size() + kBlock - 1) / kBlock;
    parallelFor(
        blocks, options.threads,
        [&](std::size_t block) {
            std::vector<RayHit> hits;
            NearestScratch scratch;
            for (std::size_t j = block * kBlock; j < std::min(results.size(), (block + 1) * kBlock); ++j)
                results[j] = nearestVisibleBones(glm::dvec3(mesh.positions[j]), rig, options.tieTolerance,
                                                 visibility ? &*visibility : nullptr, scratch, hits);
        },
        control, "visibility");
    return assembleTerms(results, options.heatConstant, 1e-9 * sceneSize(mesh, rig));
}

} // namespace trimlab
