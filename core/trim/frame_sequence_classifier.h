#pragma once
/// \file
/// Classifies the frames of an animation one after the other, per pixel, exactly (the CPU
/// reference's rays and BVH): every frame's classified fragments (classified_fragment.h)
/// under a static rule, or under a dynamic rule against the first frame or against the
/// previous one. Against the previous frame the characterization carries from frame to
/// frame as the thesis plays an animation (8.1.2, Algorithms 8.11–8.13): each frame is
/// rasterised with the one before (DynamicFrameScene) and reads that frame's per-pixel
/// characterization bit vector, so frame t costs one pass, not t (what
/// DynamicReferenceRenderer over animationChain costs), with the same result.

#include "core/trim/classified_fragment.h"
#include "core/trim/dynamic_rule.h"
#include "core/trim/partition_characterization.h"
#include "core/trim/static_rule.h"
#include "core/view/camera.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace trimlab {

/// Which frame a dynamic rule's sets take as their reference.
enum class SequenceReference {
    First,    ///< every frame is one set against the first frame (an animation's rest pose)
    Previous, ///< one set per step, each against the frame before
};

struct SequenceRule {
    /// The rule of a static classification; under a dynamic rule, the base rule that
    /// classifies the first frame.
    StaticRule staticRule = StaticRule::AlternatingBorder;
    std::optional<DynamicRule> dynamicRule; ///< nullopt: the static rule alone
    SequenceReference reference = SequenceReference::Previous;
};

/// One frame's classified fragments per pixel.
struct FrameFragments {
    int width = 0;
    int height = 0;
    std::vector<std::vector<ClassifiedFragment>> pixels; ///< row-major, row 0 at the top
    /// 1 where a characterization overflowed (more than PartitionCharacterization::kLayers
    /// intervals on the ray): the classes there are not exact. Such a pixel stays
    /// unresolved in later frames against the previous one.
    std::vector<std::uint8_t> unresolved;
};

class FrameSequenceClassifier {
public:
    /// `triangles`: the connectivity every frame shares (indices in range of every
    /// frame). `camera` with a depth range enclosing every frame (withDepthRange).
    /// `threads` = 0: the hardware concurrency.
    FrameSequenceClassifier(std::vector<glm::uvec3> triangles, const Camera& camera, int width, int height,
                            SequenceRule rule, unsigned threads = 0);

    /// Classifies the next frame: the first call classifies the first frame by
    /// rule.staticRule alone, every later call the frame after the last one given.
    /// Throws std::invalid_argument when `positions` has another size than the first frame.
    [[nodiscard]] FrameFragments next(const std::vector<glm::vec3>& positions);

    [[nodiscard]] std::size_t framesSeen() const { return m_framesSeen; }

private:
    [[nodiscard]] FrameFragments classifyStatic(const std::vector<glm::vec3>& positions) const;
    [[nodiscard]] FrameFragments classifyDynamic(const std::vector<glm::vec3>& reference,
                                                 const std::vector<glm::vec3>& current);
    [[nodiscard]] FrameFragments emptyFrame() const;

    std::vector<glm::uvec3> m_triangles;
    Camera m_camera;
    int m_width;
    int m_height;
    SequenceRule m_rule;
    unsigned m_threads;
    std::size_t m_framesSeen = 0;
    std::vector<glm::vec3> m_first;
    std::vector<glm::vec3> m_previous;
    /// The previous frame's characterization per pixel (Previous, from the second frame on).
    std::vector<PartitionCharacterization> m_characterizations;
};

} // namespace trimlab
