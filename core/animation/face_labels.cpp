#include "core/animation/face_labels.h"

namespace trimlab {

std::vector<std::uint32_t> faceLabels(std::span<const glm::uvec3> triangles, const VertexLabeling& labeling)
{
    std::vector<std::uint32_t> labels;
    labels.reserve(triangles.size());
    for (const glm::uvec3& t : triangles) {
        const std::uint32_t a = labeling.labels[t.x];
        const std::uint32_t b = labeling.labels[t.y];
        const std::uint32_t c = labeling.labels[t.z];
        labels.push_back(b == c ? b : a);
    }
    return labels;
}

} // namespace trimlab
