#pragma once
/// \file
/// A feature's handle on the shown content (shown_content.h): what it publishes goes into
/// the layers under its owner, and nowhere else — this is the one place through which
/// poses, colours and dynamic chains reach the view. Each feature keeps a publisher per
/// owner it speaks for (the design history's tools share the design history's); a
/// default-constructed one, not yet connected to a view, publishes nothing.
///
/// Publishing makes the owner's content the layer's dominant one; withdrawing gives the
/// layer back to the owner that published before. Every call takes effect at the next
/// frame; the content is kept across OpenGL contexts until the scene changes.

#include "render/shown_content.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace trimlab::render {

class ContentPublisher {
public:
    ContentPublisher() = default;
    ContentPublisher(std::shared_ptr<ShownContent> content, ContentOwner owner);

    [[nodiscard]] ContentOwner owner() const { return m_owner; }
    /// The content published into (nullptr: not connected).
    [[nodiscard]] const std::shared_ptr<ShownContent>& content() const { return m_content; }

    /// Object 0 at `positions` (#V, object space), uploaded with normals recomputed.
    /// Throws std::invalid_argument on a vertex count mismatch or without a scene.
    void showPose(std::vector<glm::vec3> positions);
    /// Pose `pose` of `model` (a skinning of object 0's mesh), `positions` being the
    /// CPU's skinning of it: skinned on the GPU where it can be, else `positions` are
    /// uploaded. Throws as showPose, and std::invalid_argument for a pose beyond the model.
    void showSkinnedPose(std::shared_ptr<const SkinningModel> model, std::size_t pose,
                         std::vector<glm::vec3> positions);
    /// The subdivision surface of `stencils` at `controlPoints`, `positions` being the
    /// CPU's evaluation: evaluated on the GPU where it can be, else `positions` are
    /// uploaded. Throws as showPose, and std::invalid_argument for another number of
    /// control points than the stencils take.
    void showSubdivisionPose(std::shared_ptr<const SubdivisionStencils> stencils, std::vector<glm::dvec3> controlPoints,
                             std::vector<glm::vec3> positions);
    void withdrawPose();
    /// Whether this owner's pose is the one shown.
    [[nodiscard]] bool showsPose() const;

    /// One colour per scene vertex (shown_content.h); empty: withdraws this owner's
    /// colours. Throws std::invalid_argument on a count mismatch.
    void showColors(std::vector<std::uint32_t> rgba8);
    [[nodiscard]] bool showsColors() const;

    /// The dynamic rules of `chain` (its last level is the shown frame); nullptr:
    /// withdraws this owner's chain (the static rule, unless another owner has one).
    void showChain(std::shared_ptr<const DynamicChain> chain);
    /// Replaces this owner's shown level (same set, new positions: a drag). Ignored
    /// without a chain of this owner.
    void replaceShownLevel(std::shared_ptr<const DynamicChainLevel> level);
    /// The shown level becomes the reference of a new set and `level` is shown (an
    /// animation played forward): the frame characterizes one level instead of the whole
    /// history. Ignored without a chain of this owner.
    void appendLevel(std::shared_ptr<const DynamicChainLevel> level);
    /// Whether this owner's chain is the one shown.
    [[nodiscard]] bool showsChain() const;

private:
    std::shared_ptr<ShownContent> m_content;
    ContentOwner m_owner = ContentOwner::None;
};

} // namespace trimlab::render
