#pragma once
/// \file
/// What the view shows, between the document and the viewport: named layers
/// (content_owner.h), each showing one owner's content at a time, each with a version
/// that changes whenever what it shows changes.
/// - Geometry: the document's scene (objects, meshes, model matrices). Replacing it
///   empties every other layer: their content belonged to the previous meshes.
/// - Pose: object 0's positions (shown_pose.h), from the features that pose it — the
///   design history's shown frame and its drags, the skeleton panel, animation playback,
///   the skinned approximation.
/// - Colors: one RGBA8 colour per scene vertex (objects in order; red in the lowest byte,
///   as GLSL's unpackUnorm4x8 reads it) instead of the trim palette — segment colours,
///   the skinning error heat map, the skeleton's stage colours, the brush's region.
/// - Chain: the dynamic rules' chain (the design history's chain to its shown frame, an
///   animation played under a dynamic rule), its shown level replaced by drags, levels
///   appended by playback.
///
/// Features publish through a ContentPublisher (content_publisher.h), the only writer of
/// the pose, colour and chain layers; the viewport widget sets the geometry, since a new
/// scene also frames the camera. A layer keeps each owner's content and shows the
/// dominant one, as a Polyscope structure shows one dominant quantity (owned_layer.h): the
/// owner that published last among those still publishing. A skeleton pose therefore
/// replaces the design history's frame until the history changes or shows another frame
/// (and publishes again), and the brush's tint lies over the skeleton's weight colours
/// until the cursor leaves.
///
/// The renderer (viewport_renderer.h) uploads a layer when its version differs from the
/// one it uploaded last, and all of them again in a new OpenGL context. Listeners
/// (subscribe) hear of every change at once: the widget repaints, the design history
/// classifies a pose it does not own under its chain (DesignWorkspace), Mesh Statistics
/// follows the frame. Plain C++ without OpenGL, so readouts and tests ask it for the
/// shown scene (posedScene) without a context.

#include "render/content_owner.h"
#include "render/owned_layer.h"
#include "render/shown_pose.h"

#include "core/scene/scene.h"
#include "core/trim/dynamic_chain.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace trimlab::render {

/// The chain layer's content: a published chain and what drags and playback did to it.
struct ShownChain {
    std::shared_ptr<const DynamicChain> chain; ///< as published (its baseRule classifies the base mesh)
    /// The levels shown, oldest first: the chain's own, the last replaced by the latest
    /// drag, then the levels appended since. Never empty; the last is the shown frame.
    std::vector<std::shared_ptr<const DynamicChainLevel>> levels;
    /// Distinct for every published chain: a renderer that holds another id uploads every
    /// level, else only a replaced last level and the appended ones.
    std::uint64_t id = 0;

    [[nodiscard]] const DynamicChainLevel& shownLevel() const { return *levels.back(); }
};

class ShownContent;

/// Keeps a listener subscribed (ShownContent::subscribe) until it goes; outliving the
/// content is harmless.
class ContentSubscription {
public:
    ContentSubscription() = default;
    ~ContentSubscription();
    ContentSubscription(ContentSubscription&& other) noexcept;
    ContentSubscription& operator=(ContentSubscription&& other) noexcept;
    ContentSubscription(const ContentSubscription&) = delete;
    ContentSubscription& operator=(const ContentSubscription&) = delete;

private:
    friend class ShownContent;
    struct Listeners;
    ContentSubscription(std::weak_ptr<Listeners> listeners, int id) : m_listeners(std::move(listeners)), m_id(id) {}
    void reset();

    std::weak_ptr<Listeners> m_listeners;
    int m_id = 0;
};

class ShownContent {
public:
    /// Called after every change of what `layer` shows (a new scene: every layer).
    using Listener = std::function<void(ShownLayer layer)>;

    ShownContent();
    ~ShownContent();
    ShownContent(const ShownContent&) = delete;
    ShownContent& operator=(const ShownContent&) = delete;

    // The geometry.

    /// Shows `scene` (nullptr: nothing) and empties the pose, colour and chain layers.
    void setScene(std::shared_ptr<const Scene> scene);
    /// `scene` has the shown scene's objects with the same meshes and other model
    /// matrices (an object was moved): the other layers stay. Throws
    /// std::invalid_argument without a shown scene or when an object's vertex or triangle
    /// count differs.
    void setSceneTransforms(std::shared_ptr<const Scene> scene);
    [[nodiscard]] const std::shared_ptr<const Scene>& scene() const { return m_scene; }
    /// Changes with setScene only (new meshes), unlike version(Geometry).
    [[nodiscard]] std::uint64_t meshVersion() const { return m_meshVersion; }

    // What each layer shows, and whose it is (ContentOwner::None: nothing).

    [[nodiscard]] const ShownPose* pose() const { return m_pose.shown(); }
    [[nodiscard]] ContentOwner poseOwner() const { return m_pose.shownOwner(); }
    [[nodiscard]] const std::vector<std::uint32_t>* colors() const { return m_colors.shown(); }
    [[nodiscard]] ContentOwner colorOwner() const { return m_colors.shownOwner(); }
    [[nodiscard]] const ShownChain* chain() const { return m_chain.shown(); }
    [[nodiscard]] ContentOwner chainOwner() const { return m_chain.shownOwner(); }
    /// The stamp of the layer's last change: distinct for every change, never 0.
    [[nodiscard]] std::uint64_t version(ShownLayer layer) const;

    /// What the view shows: the scene with the shown pose as object 0's positions
    /// (nullptr without a scene). Kept until the geometry or the pose changes.
    [[nodiscard]] std::shared_ptr<const Scene> posedScene() const;

    /// `listener` hears of every change until the subscription goes. A listener may
    /// publish; it is told of that change too, after the current one.
    [[nodiscard]] ContentSubscription subscribe(Listener listener) const;

private:
    friend class ContentPublisher;

    void publishPose(ContentOwner owner, ShownPose pose);
    void withdrawPose(ContentOwner owner);
    void publishColors(ContentOwner owner, std::vector<std::uint32_t> rgba8);
    void withdrawColors(ContentOwner owner);
    void publishChain(ContentOwner owner, std::shared_ptr<const DynamicChain> chain);
    void withdrawChain(ContentOwner owner);
    void replaceShownLevel(ContentOwner owner, std::shared_ptr<const DynamicChainLevel> level);
    void appendLevel(ContentOwner owner, std::shared_ptr<const DynamicChainLevel> level);
    [[nodiscard]] std::size_t objectZeroVertices() const;
    [[nodiscard]] std::size_t sceneVertices() const;
    void changed(ShownLayer layer);

    std::shared_ptr<const Scene> m_scene;
    std::uint64_t m_stamp = 1;
    std::uint64_t m_geometryVersion = 1;
    std::uint64_t m_meshVersion = 1;
    std::uint64_t m_chainIds = 0;
    OwnedLayer<ShownPose> m_pose;
    OwnedLayer<std::vector<std::uint32_t>> m_colors;
    OwnedLayer<ShownChain> m_chain;
    mutable std::shared_ptr<const Scene> m_posedScene;                    ///< for m_posedVersion
    mutable std::pair<std::uint64_t, std::uint64_t> m_posedVersion{0, 0}; ///< geometry and pose versions
    std::shared_ptr<ContentSubscription::Listeners> m_listeners;
};

} // namespace trimlab::render
