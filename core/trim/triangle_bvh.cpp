// Compiled with -ffp-contract=off (see core/trim/CMakeLists.txt), like ray_triangle.cpp.
#include "core/trim/triangle_bvh.h"

#include "core/scene/world_geometry.h"
#include "core/trim/ray_triangle.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace trimlab {

namespace {

constexpr int kBinCount = 16;
constexpr std::uint32_t kMaxLeafSize = 4;
constexpr std::uint32_t kMaxSahLeafSize = 16; // a leaf may win the SAH up to this size
constexpr int kMaxDepth = 60;                 // also bounds the traversal stack
constexpr double kTraversalCost = 1.0;        // relative to one triangle test

bool isFinite(const glm::dvec3& p)
{
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// Half the surface area of a box (the SAH only compares ratios).
double halfArea(const Bounds& b)
{
    if (!b.valid())
        return 0.0;
    const glm::dvec3 e = b.max - b.min;
    return e.x * e.y + e.y * e.z + e.z * e.x;
}

Bounds triangleBounds(const BvhTriangle& t)
{
    Bounds b;
    b.extend(t.a);
    b.extend(t.b);
    b.extend(t.c);
    return b;
}

struct BuildItem {
    Bounds box;
    glm::dvec3 centroid;
};

struct Split {
    int axis = -1;
    int lastLeftBin = 0;
    double cost = std::numeric_limits<double>::infinity();
};

int binOf(double coordinate, double lower, double scale)
{
    return std::clamp(static_cast<int>((coordinate - lower) * scale), 0, kBinCount - 1);
}

// Best binned-SAH split of items[order[begin..end)] over all three axes; axis -1 if the
// centroids coincide on every axis.
Split findSplit(const std::vector<BuildItem>& items, const std::vector<std::uint32_t>& order, std::uint32_t begin,
                std::uint32_t end, const Bounds& centroids)
{
    Split best;
    for (int axis = 0; axis < 3; ++axis) {
        const double extent = centroids.max[axis] - centroids.min[axis];
        if (!(extent > 0.0))
            continue;
        const double scale = kBinCount / extent;
        std::array<Bounds, kBinCount> boxes{};
        std::array<std::uint32_t, kBinCount> counts{};
        for (std::uint32_t i = begin; i < end; ++i) {
            const BuildItem& item = items[order[i]];
            const int bin = binOf(item.centroid[axis], centroids.min[axis], scale);
            boxes[bin].extend(item.box);
            ++counts[bin];
        }
        std::array<double, kBinCount> rightCost{};
        Bounds right;
        std::uint32_t rightCount = 0;
        for (int bin = kBinCount - 1; bin > 0; --bin) {
            right.extend(boxes[bin]);
            rightCount += counts[bin];
            rightCost[bin] = rightCount * halfArea(right);
        }
        Bounds left;
        std::uint32_t leftCount = 0;
        for (int bin = 0; bin < kBinCount - 1; ++bin) {
            left.extend(boxes[bin]);
            leftCount += counts[bin];
            const bool bothSidesUsed = leftCount > 0 && leftCount < end - begin;
            const double cost = leftCount * halfArea(left) + rightCost[bin + 1];
            if (bothSidesUsed && cost < best.cost)
                best = {axis, bin, cost};
        }
    }
    return best;
}

struct BuildTask {
    std::uint32_t begin;
    std::uint32_t end;
    int depth;
    std::int64_t parent; // inner node whose right-child index this task fills, or -1
};

// Decides whether a node becomes a leaf (nullopt) or where its range splits; partitions
// order[begin..end) accordingly.
std::optional<std::uint32_t> chooseSplit(const std::vector<BuildItem>& items, std::vector<std::uint32_t>& order,
                                         const BuildTask& task, const Bounds& box, const Bounds& centroids)
{
    const std::uint32_t count = task.end - task.begin;
    if (count <= kMaxLeafSize || task.depth >= kMaxDepth)
        return std::nullopt;
    const Split split = findSplit(items, order, task.begin, task.end, centroids);
    if (split.axis < 0) // every centroid coincides: split by array position if large
        return count <= kMaxSahLeafSize ? std::nullopt : std::optional(task.begin + count / 2);
    const double leafCost = count * halfArea(box);
    if (count <= kMaxSahLeafSize && leafCost <= split.cost + kTraversalCost * halfArea(box))
        return std::nullopt;
    const int axis = split.axis;
    const double scale = kBinCount / (centroids.max[axis] - centroids.min[axis]);
    const auto middle = std::partition(order.begin() + task.begin, order.begin() + task.end, [&](std::uint32_t i) {
        return binOf(items[i].centroid[axis], centroids.min[axis], scale) <= split.lastLeftBin;
    });
    return std::uint32_t(middle - order.begin());
}

} // namespace

std::vector<BvhTriangle> collectWorldTriangles(const Scene& scene)
{
    std::vector<BvhTriangle> triangles;
    triangles.reserve(scene.triangleCount());
    for (std::size_t objectId = 0; objectId < scene.objects.size(); ++objectId) {
        const SceneObject& object = scene.objects[objectId];
        const std::vector<glm::dvec3> world = worldPositions(object);
        for (std::size_t f = 0; f < object.mesh.triangles.size(); ++f) {
            const glm::uvec3 t = object.mesh.triangles[f];
            if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
                continue;
            const BvhTriangle tri{world[t[0]], world[t[1]], world[t[2]], int(objectId), int(f)};
            if (!isFinite(tri.a) || !isFinite(tri.b) || !isFinite(tri.c))
                continue;
            if (tri.a == tri.b || tri.b == tri.c || tri.c == tri.a)
                continue; // two edge functions are exact negatives, the third zero: never hit
            triangles.push_back(tri);
        }
    }
    return triangles;
}

TriangleBvh::TriangleBvh(const Scene& scene)
{
    build(collectWorldTriangles(scene));
}

void TriangleBvh::build(std::vector<BvhTriangle> triangles)
{
    std::vector<BuildItem> items(triangles.size());
    Bounds sceneBox;
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        items[i].box = triangleBounds(triangles[i]);
        items[i].centroid = items[i].box.center();
        sceneBox.extend(items[i].box);
    }
    m_center = sceneBox.valid() ? sceneBox.center() : glm::dvec3(0.0);
    m_radius = sceneBox.radius();
    std::vector<std::uint32_t> order(triangles.size());
    for (std::uint32_t i = 0; i < order.size(); ++i)
        order[i] = i;
    m_nodes.clear();
    m_depth = 0;
    if (order.empty())
        return;
    std::vector<BuildTask> stack{{0, std::uint32_t(order.size()), 0, -1}};
    while (!stack.empty()) {
        const BuildTask task = stack.back();
        stack.pop_back();
        const auto nodeIndex = std::uint32_t(m_nodes.size());
        if (task.parent >= 0)
            m_nodes[std::size_t(task.parent)].index = nodeIndex;
        m_depth = std::max(m_depth, task.depth);
        Bounds box;
        Bounds centroids;
        for (std::uint32_t i = task.begin; i < task.end; ++i) {
            box.extend(items[order[i]].box);
            centroids.extend(items[order[i]].centroid);
        }
        BvhNode node;
        node.lower = box.valid() ? box.min : glm::dvec3(0.0);
        node.upper = box.valid() ? box.max : glm::dvec3(0.0);
        const std::optional<std::uint32_t> middle = chooseSplit(items, order, task, box, centroids);
        if (!middle) {
            node.index = task.begin;
            node.count = task.end - task.begin;
        }
        m_nodes.push_back(node);
        if (middle) { // left child is the next node: push it last
            stack.push_back({*middle, task.end, task.depth + 1, std::int64_t(nodeIndex)});
            stack.push_back({task.begin, *middle, task.depth + 1, -1});
        }
    }
    m_triangles.resize(triangles.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        m_triangles[i] = triangles[order[i]];
}

namespace {

// Conservative slab test against a box padded by `pad` on every side.
struct BoxRay {
    glm::dvec3 origin;
    glm::dvec3 invDirection;
    bool parallel[3];
    double pad;
};

// The t at which the ray enters the padded box within [tMin, tMax]; none if it misses.
std::optional<double> boxEntry(const BoxRay& ray, const BvhNode& node, double tMin, double tMax)
{
    double tNear = tMin;
    double tFar = tMax;
    for (int axis = 0; axis < 3; ++axis) {
        const double lower = node.lower[axis] - ray.pad;
        const double upper = node.upper[axis] + ray.pad;
        if (ray.parallel[axis]) {
            if (ray.origin[axis] < lower || ray.origin[axis] > upper)
                return std::nullopt;
            continue;
        }
        double t0 = (lower - ray.origin[axis]) * ray.invDirection[axis];
        double t1 = (upper - ray.origin[axis]) * ray.invDirection[axis];
        if (t0 > t1)
            std::swap(t0, t1);
        tNear = std::max(tNear, t0);
        tFar = std::min(tFar, t1);
        if (tNear > tFar)
            return std::nullopt;
    }
    return tNear;
}

bool hitsBox(const BoxRay& ray, const BvhNode& node, double tMin, double tMax)
{
    return boxEntry(ray, node, tMin, tMax).has_value();
}

// The box ray of `ray` for a tree whose triangles lie within `radius` of `center`.
BoxRay makeBoxRay(const PixelRay& ray, const glm::dvec3& center, double radius)
{
    BoxRay boxRay{ray.origin, glm::dvec3(0.0), {false, false, false}, 0.0};
    for (int axis = 0; axis < 3; ++axis) {
        boxRay.parallel[axis] = ray.direction[axis] == 0.0;
        boxRay.invDirection[axis] = boxRay.parallel[axis] ? 0.0 : 1.0 / ray.direction[axis];
    }
    // Far above the rounding of the box and shear arithmetic (~1e-15 of the distance),
    // far below any geometric feature; the triangle test decides exactly afterwards.
    const double distanceScale = glm::length(ray.origin - center) + radius;
    boxRay.pad = 1e-10 * distanceScale + std::numeric_limits<double>::min();
    return boxRay;
}

} // namespace

void TriangleBvh::intersectAll(const PixelRay& ray, double tMin, double tMax, std::vector<RayHit>& hits) const
{
    if (m_nodes.empty() || !(tMin <= tMax))
        return;
    const WatertightRay watertight = makeWatertightRay(ray);
    const BoxRay boxRay = makeBoxRay(ray, m_center, m_radius);
    // Boxes are tested on a slightly wider t range, so the exact range test is left to t.
    const double tSlack = 1e-10 * (std::abs(tMin) + std::abs(tMax));
    std::array<std::uint32_t, kMaxDepth + 4> stack{};
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const BvhNode& node = m_nodes[stack[--top]];
        if (!hitsBox(boxRay, node, tMin - tSlack, tMax + tSlack))
            continue;
        if (node.count == 0) {
            stack[top++] = node.index;
            stack[top++] = std::uint32_t(&node - m_nodes.data()) + 1;
            continue;
        }
        for (std::uint32_t i = node.index; i < node.index + node.count; ++i) {
            const BvhTriangle& tri = m_triangles[i];
            const std::optional<TriangleHit> hit = intersectTriangle(watertight, tri.a, tri.b, tri.c);
            if (hit && hit->t >= tMin && hit->t <= tMax)
                hits.push_back({hit->t, tri.objectId, tri.primitiveId, hit->facing, hit->u, hit->v});
        }
    }
}

std::optional<RayHit> TriangleBvh::intersectNearest(const PixelRay& ray, double tMin, double tMax) const
{
    if (m_nodes.empty() || !(tMin <= tMax))
        return std::nullopt;
    const WatertightRay watertight = makeWatertightRay(ray);
    const BoxRay boxRay = makeBoxRay(ray, m_center, m_radius);
    // The slack of the whole range, kept while the range shrinks: a box is skipped only when
    // intersectAll would skip it for a range ending at the best hit.
    const double tSlack = 1e-10 * (std::abs(tMin) + std::abs(tMax));
    std::optional<RayHit> best;
    std::array<std::pair<std::uint32_t, double>, kMaxDepth + 4> stack{}; // node, entry t
    int top = 0;
    if (const std::optional<double> entry = boxEntry(boxRay, m_nodes[0], tMin - tSlack, tMax + tSlack))
        stack[top++] = {0u, *entry};
    while (top > 0) {
        const auto [index, entry] = stack[--top];
        if (entry > tMax + tSlack) // the best hit, found since this box was pushed, is nearer
            continue;
        const BvhNode& node = m_nodes[index];
        if (node.count == 0) {
            const std::uint32_t left = index + 1;
            const std::uint32_t right = node.index;
            const std::optional<double> leftEntry = boxEntry(boxRay, m_nodes[left], tMin - tSlack, tMax + tSlack);
            const std::optional<double> rightEntry = boxEntry(boxRay, m_nodes[right], tMin - tSlack, tMax + tSlack);
            // The farther child goes on the stack first, so the nearer one is taken next.
            const bool leftFirst = leftEntry && (!rightEntry || *leftEntry <= *rightEntry);
            if (leftFirst) {
                if (rightEntry)
                    stack[top++] = {right, *rightEntry};
                stack[top++] = {left, *leftEntry};
            } else if (rightEntry) {
                if (leftEntry)
                    stack[top++] = {left, *leftEntry};
                stack[top++] = {right, *rightEntry};
            }
            continue;
        }
        for (std::uint32_t i = node.index; i < node.index + node.count; ++i) {
            const BvhTriangle& tri = m_triangles[i];
            const std::optional<TriangleHit> hit = intersectTriangle(watertight, tri.a, tri.b, tri.c);
            if (hit && hit->t >= tMin && hit->t <= tMax) {
                best = RayHit{hit->t, tri.objectId, tri.primitiveId, hit->facing, hit->u, hit->v};
                tMax = hit->t;
            }
        }
    }
    return best;
}

} // namespace trimlab
