#pragma once
/// \file
/// The homogeneous confluent rule (thesis 8.1.1) forbids deforming surface parts that
/// were trimmed off. Before a stroke starts, the brush asks whether any vertex of its
/// region lies off the trim of the shown frame under the dynamic rules. The exact test
/// (trim/trim_membership.h) casts rays through the whole chain, so only a sample of the
/// region is tested: at most kMaxSamples vertices spread over it, always including the
/// corners of the grabbed triangle.

#include "core/deform/brush_stroke.h"
#include "core/trim/dynamic_reference_renderer.h"

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace trimlab {

class TrimmedRegionCheck {
public:
    static constexpr std::size_t kMaxSamples = 64;

    /// `chain` shows the last frame of the history (its positions are `positions`, #V,
    /// object space; the chain itself in world space through `model`).
    TrimmedRegionCheck(const DynamicChain& chain, const glm::dmat4& model);

    /// The region vertices the check tests: the corners of `anchorTriangle` and up to
    /// kMaxSamples − 3 more, evenly spread over `region` (sorted, unique).
    [[nodiscard]] static std::vector<std::uint32_t> sample(std::span<const std::uint32_t> region,
                                                           const glm::uvec3& anchorTriangle);

    /// The vertices among `vertices` that are trimmed off (not on the trim).
    /// `epsilon`: how far inside the surface each test ray starts (object-space length).
    [[nodiscard]] std::vector<std::uint32_t> trimmedOff(const deform::BrushTopology& topology,
                                                        const std::vector<glm::vec3>& positions,
                                                        std::span<const std::uint32_t> vertices, double epsilon) const;

private:
    DynamicReferenceRenderer m_reference;
    glm::dmat4 m_model;
};

} // namespace trimlab
