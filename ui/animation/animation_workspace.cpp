#include "ui/animation/animation_workspace.h"

#include "ui/animation/animation_settings_store.h"
#include "ui/animation/pose_history_bar.h"
#include "ui/animation/segmentation_panel.h"
#include "ui/animation/timeline_panel.h"
#include "ui/common/window_context.h"
#include "ui/skinning/skinning_panel.h"
#include "ui/skinning/skinning_workspace.h"
#include "ui/viewport/viewport_widget.h"

#include "core/animation/mesh_animation.h"

#include <QDockWidget>
#include <QVBoxLayout>

namespace trimlab::ui {

AnimationWorkspace::AnimationWorkspace(const WindowContext& context, ViewportWidget* viewport, QDockWidget* tabWith,
                                       QObject* parent)
    : QObject(parent),
      m_context(context),
      m_viewport(viewport),
      m_playbackShown(viewport->content(), render::ContentOwner::AnimationPlayback),
      m_skinningShown(viewport->content(), render::ContentOwner::Skinning),
      m_segmentsShown(viewport->content(), render::ContentOwner::Segmentation),
      m_player(m_playbackShown)
{
    createDocks(tabWith);
    connectParts();
}

void AnimationWorkspace::createDocks(QDockWidget* tabWith)
{
    m_timeline = new TimelinePanel;
    m_history = new PoseHistoryBar;
    auto* timeline = new QWidget;
    auto* layout = new QVBoxLayout(timeline);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(m_timeline);
    m_history->setContentsMargins(9, 0, 9, 6); // aligned with the timeline row's controls
    layout->addWidget(m_history);
    m_timelineDock = m_context.addBottomDock(tr("Timeline"), QStringLiteral("timelineDock"), timeline);
    m_timelineDock->hide(); // shown while an animation is open
    m_segmentation = new SegmentationPanel;
    m_segmentationDock =
        m_context.addSideDock(tr("Segmentation"), QStringLiteral("segmentationDock"), m_segmentation, tabWith);
    m_skinning = new SkinningWorkspace(m_context, m_segmentationDock, this);
}

void AnimationWorkspace::connectParts()
{
    QSettings& settings = m_context.settings();
    connect(m_timeline, &TimelinePanel::poseChanged, this, &AnimationWorkspace::showPose);
    connect(m_timeline, &TimelinePanel::playbackChoicesChanged, this, [this, &settings] {
        savePlaybackChoices(settings, {m_timeline->fps(), m_timeline->loops()});
    });
    connect(m_history, &PoseHistoryBar::choicesChanged, this, [this, &settings] {
        savePoseHistoryChoices(settings, m_history->choices());
        applyPoseHistoryChoices();
    });
    connect(m_viewport, &ViewportWidget::frameRendered, this, &AnimationWorkspace::showHistoryStatus);
    connect(m_segmentation, &SegmentationPanel::displayColorsChanged, this, &AnimationWorkspace::showSegmentColors);
    connect(m_segmentation, &SegmentationPanel::choicesChanged, this,
            [this, &settings] { saveSegmentationChoices(settings, m_segmentation->choices()); });
    connect(m_segmentation, &SegmentationPanel::streamStarted, this, [this] {
        m_timeline->setPose(0);
        m_timeline->play();
    });
    connect(m_segmentation, &SegmentationPanel::exportRequested, this,
            &AnimationWorkspace::showExportSegmentationDialog);
    connect(m_segmentation, &SegmentationPanel::displayColorsChanged, this,
            &AnimationWorkspace::passSegmentationToSkinning);
    connect(m_segmentation, &SegmentationPanel::choicesChanged, this, &AnimationWorkspace::passSegmentationToSkinning);
    connect(m_skinning->panel(), &SkinningPanel::displayChanged, this, [this] {
        m_player.invalidate(); // the approximation's poses replace the captured ones, or the reverse
        showPose(m_timeline->pose());
        showSegmentColors();
    });
    connect(m_skinning, &SkinningWorkspace::exportRequested, this,
            [this] { m_skinning->showExportDialog(double(m_timeline->fps())); });
}

void AnimationWorkspace::restoreSettings()
{
    m_segmentation->setChoices(loadSegmentationChoices(m_context.settings()));
    const PlaybackChoices playback = loadPlaybackChoices(m_context.settings());
    m_timeline->setPlaybackChoices(playback.fps, playback.loop);
    m_history->setChoices(loadPoseHistoryChoices(m_context.settings()));
    m_player.setChoices(m_history->choices(), m_baseRule);
}

void AnimationWorkspace::setBaseRule(StaticRule rule)
{
    if (rule == m_baseRule)
        return;
    m_baseRule = rule;
    applyPoseHistoryChoices();
}

void AnimationWorkspace::applyPoseHistoryChoices()
{
    m_player.setChoices(m_history->choices(), m_baseRule);
    if (m_animation)
        showPose(m_timeline->pose());
}

// The sets of the pose shown and what the last frame characterized: the cost of the
// history, which grows with the pose against the previous pose.
void AnimationWorkspace::showHistoryStatus()
{
    if (!m_animation || !m_player.choices().rule)
        return;
    const std::optional<render::DynamicFrameStats>& stats = m_viewport->lastDynamicStats();
    if (!stats) {
        m_history->setStatus(tr("rest pose: the static rule"));
        return;
    }
    const QString sets = stats->levels == 1 ? tr("1 set") : tr("%1 sets").arg(stats->levels);
    m_history->setStatus(tr("%1, %2 characterized this frame").arg(sets).arg(stats->characterizedLevels));
}

std::vector<glm::vec3> AnimationWorkspace::shownPositions(std::size_t pose) const
{
    if (std::optional<std::vector<glm::vec3>> skinned = m_skinning->panel()->shownPose(int(pose)))
        return std::move(*skinned);
    return m_animation->animation->poses[pose];
}

void AnimationWorkspace::hideAnimationDocks()
{
    m_timelineDock->hide(); // until an animation is opened
    m_segmentationDock->hide();
    m_skinning->dock()->hide();
}

void AnimationWorkspace::show(std::shared_ptr<const LoadedAnimation> animation)
{
    m_animation = std::move(animation);
    const MeshAnimation& poses = *m_animation->animation;
    QStringList names;
    for (std::size_t pose = 0; pose < poses.poseCount(); ++pose)
        names << (pose < poses.poseNames.size() ? QString::fromStdString(poses.poseNames[pose])
                                                : tr("pose %1").arg(pose));
    m_timeline->setPoses(names);
    m_player.setAnimation(m_animation->animation, [this](std::size_t pose) { return shownPositions(pose); });
    m_segmentation->setAnimation(m_animation);
    m_skinning->panel()->setAnimation(m_animation);
    passSegmentationToSkinning();
    m_timelineDock->show();
    m_skinning->dock()->show();
    m_segmentationDock->show();
    m_segmentationDock->raise();
}

bool AnimationWorkspace::confirmDiscardSkinningEdits()
{
    return m_skinning->confirmDiscardEdits(double(m_timeline->fps()));
}

void AnimationWorkspace::clear()
{
    if (!m_animation)
        return;
    m_animation.reset();
    m_player.setAnimation(nullptr, {});
    m_history->setStatus({});
    m_timeline->setPoses({});
    m_segmentation->setAnimation(nullptr);
    m_skinning->panel()->setAnimation(nullptr);
    hideAnimationDocks();
}

// The pose shown, captured or approximated (skinned on the GPU where it can be), and
// under a dynamic rule its chain; each owner's pose is published first, so the other's
// withdrawal changes nothing shown.
void AnimationWorkspace::showPose(int pose)
{
    if (!m_animation || pose < 0 || std::size_t(pose) >= m_animation->animation->poseCount())
        return;
    const auto index = std::size_t(pose);
    if (std::optional<std::vector<glm::vec3>> skinned = m_skinning->panel()->shownPose(pose)) {
        m_skinningShown.showSkinnedPose(m_skinning->panel()->shownModel(pose), index, std::move(*skinned));
        m_playbackShown.withdrawPose();
    } else {
        if (m_animation->fileSkin) // a skinned glTF file plays on the GPU from its own skin
            m_playbackShown.showSkinnedPose(m_animation->fileSkin, index, m_animation->animation->poses[index]);
        else
            m_playbackShown.showPose(m_animation->animation->poses[index]);
        m_skinningShown.withdrawPose();
    }
    m_player.show(index);
    m_segmentation->setCurrentPose(pose);
    m_skinning->panel()->setCurrentPose(pose);
}

// The skinning error heat map, while shown, takes the place of the segment colors.
void AnimationWorkspace::showSegmentColors()
{
    if (!m_animation)
        return;
    const std::vector<std::uint32_t>& heatMap = m_skinning->panel()->displayColors();
    if (heatMap.empty()) {
        m_segmentsShown.showColors(m_segmentation->displayColors());
        m_skinningShown.showColors({});
    } else {
        m_skinningShown.showColors(heatMap);
        m_segmentsShown.showColors({});
    }
}

// The Skinning panel's bones: the segmentation shown, unless it changes per pose
// (variable mode); a given bone count segments with the Segmentation panel's settings.
void AnimationWorkspace::passSegmentationToSkinning()
{
    const bool variable = m_segmentation->choices().mode == SegmentationMode::Variable;
    SkinningPanel* skinning = m_skinning->panel();
    skinning->setSegmentation(variable ? nullptr : m_segmentation->shownLabeling(),
                              variable ? nullptr : m_segmentation->shownColors());
    skinning->setSegmenterSettings(m_segmentation->choices().segmenterSettings());
}

void AnimationWorkspace::showExportSegmentationDialog()
{
    const QString path =
        m_context.askSavePath(tr("Export Segmentation"),
                              {tr("Segmentation JSON (*.json)"), tr("Per-vertex labels CSV (*.csv)"),
                               tr("glTF with segment colors (*.gltf)")},
                              m_context.sceneBaseName(QStringLiteral("animation")) + QStringLiteral("-segments.json"));
    if (path.isEmpty())
        return;
    QString error;
    if (m_segmentation->exportSegmentation(path, &error))
        m_context.showStatus(tr("Saved %1").arg(path));
    else
        m_context.showMessage(QMessageBox::Warning, tr("Export Segmentation"), tr("The segmentation was not saved."),
                              error);
}

} // namespace trimlab::ui
