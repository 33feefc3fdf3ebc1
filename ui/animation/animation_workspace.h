#pragma once
/// \file
/// The mesh-animation feature of the main window, for the animation shown (its rest pose
/// is the window's scene): the Timeline dock at the bottom, which plays the poses in the
/// viewport; the Segmentation dock (thesis chapter 3), which segments the animation and
/// colours it by segment; and the skinning feature (skinning/skinning_workspace.h), whose
/// bones are the segmentation shown and whose approximation or error heat map, while
/// shown, takes the place of the original poses and the segment colours. The Timeline's
/// second row (pose_history_bar.h) plays the poses — captured or approximated — under a
/// dynamic rule when the user picks one (dynamic_pose_player.h). The Timeline and
/// Skinning docks are shown only while an animation is. Playback, pose classification and
/// segmentation choices persist in the settings.
///
/// What it shows goes into the viewport's content (render/content_publisher.h) under three
/// owners: animation playback (the pose on the timeline, its chain under a dynamic rule),
/// skinning (the approximation's pose and the error heat map, which take the place of the
/// captured pose and the segment colours while shown) and segmentation (the segment
/// colours).
///
/// Opening an animation (AnimationOpener, recent animations, the dialog) is the window's:
/// it calls show() with what was loaded.

#include "ui/animation/dynamic_pose_player.h"
#include "ui/common/loaded_animation.h"

#include "render/content_publisher.h"

#include <QObject>

#include <memory>

class QDockWidget;

namespace trimlab::ui {

class PoseHistoryBar;
class SegmentationPanel;
class SkinningWorkspace;
class TimelinePanel;
class ViewportWidget;
class WindowContext;

class AnimationWorkspace : public QObject {
    Q_OBJECT
public:
    /// The Segmentation dock is tabbed with `tabWith`, the Skinning dock with it.
    AnimationWorkspace(const WindowContext& context, ViewportWidget* viewport, QDockWidget* tabWith,
                       QObject* parent = nullptr);

    [[nodiscard]] TimelinePanel* timelinePanel() const { return m_timeline; }
    [[nodiscard]] PoseHistoryBar* poseHistoryBar() const { return m_history; }
    [[nodiscard]] SegmentationPanel* segmentationPanel() const { return m_segmentation; }
    [[nodiscard]] SkinningWorkspace* skinning() const { return m_skinning; }
    /// SkinningWorkspace::confirmDiscardEdits at the timeline's rate.
    [[nodiscard]] bool confirmDiscardSkinningEdits();
    [[nodiscard]] QDockWidget* timelineDock() const { return m_timelineDock; }
    [[nodiscard]] QDockWidget* segmentationDock() const { return m_segmentationDock; }
    /// The animation shown (nullptr: none).
    [[nodiscard]] const std::shared_ptr<const LoadedAnimation>& animation() const { return m_animation; }

    /// Shows `animation` (the viewport shows its rest scene already): its poses on the
    /// timeline, the panels on it, the Timeline and Skinning docks.
    void show(std::shared_ptr<const LoadedAnimation> animation);
    /// No animation any more (another scene is shown); no-op without one.
    void clear();
    /// The saved playback and segmentation choices into the panels.
    void restoreSettings();
    /// Hides the docks that belong to a shown animation (after the window state was restored).
    void hideAnimationDocks();
    /// The Render panel's static rule, which classifies the rest pose of a history played
    /// under a dynamic rule.
    void setBaseRule(StaticRule rule);

private:
    void createDocks(QDockWidget* tabWith);
    void connectParts();
    void showPose(int pose);
    void applyPoseHistoryChoices();
    void showHistoryStatus();
    [[nodiscard]] std::vector<glm::vec3> shownPositions(std::size_t pose) const;
    void showSegmentColors();
    void passSegmentationToSkinning();
    void showExportSegmentationDialog();

    const WindowContext& m_context;
    ViewportWidget* m_viewport;
    render::ContentPublisher m_playbackShown;
    render::ContentPublisher m_skinningShown;
    render::ContentPublisher m_segmentsShown;
    TimelinePanel* m_timeline = nullptr;
    PoseHistoryBar* m_history = nullptr;
    DynamicPosePlayer m_player;
    StaticRule m_baseRule = StaticRule::AlternatingBorder;
    QDockWidget* m_timelineDock = nullptr;
    SegmentationPanel* m_segmentation = nullptr;
    QDockWidget* m_segmentationDock = nullptr;
    SkinningWorkspace* m_skinning = nullptr;
    std::shared_ptr<const LoadedAnimation> m_animation;
};

} // namespace trimlab::ui
