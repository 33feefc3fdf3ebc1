#include "core/skeleton/skeleton_stage_colors.h"

#include "core/image/heat_map_colors.h"
#include "core/image/packed_rgba8.h"

#include "core/animation/color_wheel.h"

#include <algorithm>
#include <cmath>

namespace trimlab {

namespace {

const std::uint32_t kGrey = packRgba8(glm::vec3(0.6f));

// The smallest palette index unused by any neighbour, node by node (a tree needs two,
// junctions a few more).
std::vector<int> greedyNodeColors(const CurveSkeleton& curve)
{
    const std::size_t n = curve.nodes.size();
    std::vector<std::vector<int>> neighbours(n);
    for (const auto& [a, b] : curve.edges) {
        if (a < 0 || b < 0 || std::size_t(a) >= n || std::size_t(b) >= n)
            continue;
        neighbours[std::size_t(a)].push_back(b);
        neighbours[std::size_t(b)].push_back(a);
    }
    std::vector<int> color(n, -1);
    for (std::size_t k = 0; k < n; ++k) {
        int c = 0;
        while (
            std::any_of(neighbours[k].begin(), neighbours[k].end(), [&](int m) { return color[std::size_t(m)] == c; }))
            ++c;
        color[k] = c;
    }
    return color;
}

} // namespace

std::vector<std::uint32_t> laplacianColors(std::span<const double> magnitude, double& largest)
{
    std::vector<double> values(magnitude.begin(), magnitude.end());
    largest = 0.0;
    for (double& v : values) {
        if (!std::isfinite(v))
            v = 0.0;
        largest = std::max(largest, v);
    }
    return heatMapRgba8(values, largest);
}

std::vector<std::uint32_t> curveMappingColors(const CurveSkeleton& curve)
{
    const std::vector<int> nodeColor = greedyNodeColors(curve);
    std::vector<std::uint32_t> colors(curve.vertexNode.size(), kGrey);
    for (std::size_t v = 0; v < colors.size(); ++v) {
        const int node = curve.vertexNode[v];
        if (node >= 0 && std::size_t(node) < nodeColor.size())
            colors[v] = packRgba8(paletteColor(std::size_t(nodeColor[std::size_t(node)])).rgb());
    }
    return colors;
}

std::vector<std::uint32_t> jointSegmentColors(const SkeletonRig& rig)
{
    std::vector<std::uint32_t> colors(rig.vertexJoint.size(), kGrey);
    for (std::size_t v = 0; v < colors.size(); ++v) {
        const int joint = rig.vertexJoint[v];
        if (joint >= 0 && std::size_t(joint) < rig.joints.size())
            colors[v] = packRgba8(paletteColor(std::size_t(joint)).rgb());
    }
    return colors;
}

std::vector<std::uint32_t> boneWeightColors(std::span<const double> column)
{
    std::vector<double> values(column.begin(), column.end());
    for (double& v : values)
        v = std::isfinite(v) ? std::clamp(v, 0.0, 1.0) : 0.0;
    return heatMapRgba8(values, 1.0);
}

} // namespace trimlab
