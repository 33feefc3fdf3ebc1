#include "ui/skinning/skinning_panel.h"

#include "core/image/heat_map_colors.h"
#include "ui/common/heat_map_legend.h"
#include "ui/common/job_presenter.h"
#include "ui/common/loaded_animation.h"
#include "ui/common/parameter_form.h"
#include "ui/common/run_cancel_row.h"
#include "ui/common/undo_buttons.h"
#include "ui/skinning/skinning_bone_editor.h"
#include "ui/skinning/skinning_error_chart.h"
#include "ui/skinning/skinning_session.h"
#include "ui/skinning/skinning_settings_form.h"

#include "core/skinning/skinning_error.h"
#include "core/skinning/skinning_gltf.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <glm/geometric.hpp>

#include <algorithm>
#include <filesystem>
#include <stdexcept>

namespace trimlab::ui {

namespace {

QString milliseconds(double ms)
{
    return QStringLiteral("%1 ms").arg(ms, 0, 'f', ms < 10.0 ? 2 : 1);
}

/// The stages that ran (a correction's time is 0 when it was not asked for), and whether
/// each correction was kept.
QString stageTimesText(const SkinningFitResult& result)
{
    const SkinningStageTimes& t = result.times;
    QStringList parts{SkinningPanel::tr("weights %1").arg(milliseconds(t.weightsMs)),
                      SkinningPanel::tr("fit %1").arg(milliseconds(t.fitMs))};
    const QString dropped = SkinningPanel::tr(" (dropped: E_RMS rose)");
    if (t.weightCorrectionMs > 0.0)
        parts << SkinningPanel::tr("weight corrections %1%2")
                     .arg(milliseconds(t.weightCorrectionMs), result.weightCorrectionsKept ? QString() : dropped);
    if (t.vertexCorrectionMs > 0.0)
        parts << SkinningPanel::tr("vertex corrections %1%2")
                     .arg(milliseconds(t.vertexCorrectionMs), result.vertexCorrectionsKept ? QString() : dropped);
    parts << SkinningPanel::tr("error %1").arg(milliseconds(t.errorMs))
          << SkinningPanel::tr("total %1").arg(milliseconds(t.totalMs));
    return parts.join(QStringLiteral(" · "));
}

} // namespace

SkinningPanel::SkinningPanel(QWidget* parent) : QWidget(parent)
{
    m_job = new BackgroundJob<std::shared_ptr<const SkinningFit>>(this);
    m_exportJob = new BackgroundJob<ExportOutcome>(this);
    m_form = new SkinningSettingsForm;
    m_progress = new QProgressBar;
    m_progress->setObjectName(QStringLiteral("skinningProgressBar"));
    m_status = new QLabel;
    m_status->setObjectName(QStringLiteral("skinningStatusLabel"));
    m_status->setWordWrap(true);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_form);
    layout->addWidget(createFitRow());
    layout->addWidget(m_progress);
    layout->addWidget(m_status);
    layout->addWidget(createResultGroup());
    layout->addWidget(createEditGroup());
    layout->addWidget(createExportRow());
    layout->addStretch();
    connect(m_form, &SkinningSettingsForm::changed, this, &SkinningPanel::onFormChanged);
    connectJob();
    connectExportJob();
    setAnimation(nullptr);
}

SkinningPanel::~SkinningPanel() = default;

QWidget* SkinningPanel::createFitRow()
{
    m_fit = new QPushButton(tr("Fit"));
    m_fit->setObjectName(QStringLiteral("fitSkinningButton"));
    m_fit->setToolTip(tr("Fit bone transforms (and weights) to every pose"));
    m_cancel = new QPushButton(tr("Cancel"));
    m_cancel->setObjectName(QStringLiteral("cancelSkinningButton"));
    connect(m_fit, &QPushButton::clicked, this, &SkinningPanel::fit);
    connect(m_cancel, &QPushButton::clicked, this, &SkinningPanel::cancel);
    return runCancelRow(m_fit, m_cancel);
}

QWidget* SkinningPanel::createResultGroup()
{
    auto* group = new QGroupBox(tr("Approximation"));
    m_error = new QLabel;
    m_error->setObjectName(QStringLiteral("skinningErrorLabel"));
    m_error->setWordWrap(true);
    m_error->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_error->setToolTip(tr("E_RMS = 1000·‖A − A′‖_F / √(3nk): thousandths of the animation's length unit"));
    m_times = new QLabel;
    m_times->setObjectName(QStringLiteral("skinningTimesLabel"));
    m_times->setWordWrap(true);
    m_chart = new SkinningErrorChart;
    m_viewBox = new QComboBox;
    m_viewBox->setObjectName(QStringLiteral("skinningViewComboBox"));
    m_viewBox->addItem(tr("Original"), int(SkinningView::Original));
    m_viewBox->addItem(tr("Approximation"), int(SkinningView::Approximation));
    m_viewBox->addItem(tr("Error heat map"), int(SkinningView::ErrorHeatMap));
    m_viewBox->setToolTip(tr("What the timeline plays: the original poses, their skinned approximation, or the "
                             "original colored by each vertex's error"));
    m_legend = new HeatMapLegend;
    m_legend->setVisible(false);
    connect(m_viewBox, &QComboBox::currentIndexChanged, this, &SkinningPanel::onViewChosen);
    auto* viewRow = new QFormLayout;
    viewRow->addRow(tr("Show"), m_viewBox);
    auto* layout = new QVBoxLayout(group);
    layout->addWidget(m_error);
    layout->addWidget(m_times);
    layout->addWidget(m_chart);
    layout->addLayout(viewRow);
    layout->addWidget(m_legend);
    return group;
}

QWidget* SkinningPanel::createEditGroup()
{
    auto* group = new QGroupBox(tr("Edit pose by moving a bone"));
    m_editGroup = group;
    m_editor = new SkinningBoneEditor;
    connect(m_editor, &SkinningBoneEditor::applyRequested, this, &SkinningPanel::onApplyRequested);
    auto* layout = new QVBoxLayout(group);
    layout->addWidget(m_editor);
    return group;
}

QWidget* SkinningPanel::createExportRow()
{
    m_export = new QPushButton(tr("Export glTF…"));
    m_export->setObjectName(QStringLiteral("exportSkinningButton"));
    m_export->setToolTip(tr("The approximation shown (edits included) as a glTF skin with one joint per bone, "
                            "or as morph targets"));
    m_morphTargets = new QCheckBox(tr("Morph targets"));
    m_morphTargets->setObjectName(QStringLiteral("skinningMorphTargetsCheckBox"));
    m_morphTargets->setToolTip(tr("One morph target per pose: exact, but larger than a skin. A skin carries rigid "
                                  "joints only, so an LBS fit is exported as its closest rigid motions."));
    m_interpolation = parameterComboBox(skinning_parameters::kInterpolation, "skinningInterpolationComboBox");
    connect(m_morphTargets, &QCheckBox::toggled, m_interpolation, [this](bool morph) {
        m_interpolation->setEnabled(!morph); // morph targets are exact at every pose: nothing to interpolate
    });
    connect(m_export, &QPushButton::clicked, this, &SkinningPanel::exportRequested);
    auto* row = new QWidget;
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_export);
    layout->addWidget(m_morphTargets);
    layout->addWidget(m_interpolation);
    return row;
}

void SkinningPanel::connectJob()
{
    m_presenter =
        new JobPresenter(m_job, {m_fit, m_cancel, m_progress, m_status}, JobPresenter::ProgressText::Count, this);
    connect(m_job, &BackgroundJobBase::succeeded, this, &SkinningPanel::onFitSucceeded);
    connect(m_job, &BackgroundJobBase::canceled, this, [this] {
        onFitEnded(m_fitAnimation != m_animation ? readyStatus()
                   : m_session                   ? tr("Canceled; the previous fit is kept.")
                                                 : tr("Canceled."));
    });
    connect(m_job, &BackgroundJobBase::failed, this, [this](const QString& message) {
        onFitEnded(m_fitAnimation == m_animation ? tr("Fit failed: %1").arg(message) : readyStatus());
    });
}

void SkinningPanel::connectExportJob()
{
    connect(m_exportJob, &BackgroundJobBase::succeeded, this, [this] {
        const ExportOutcome outcome = m_exportJob->takeResult();
        setStatus(tr("Exported %1.").arg(m_exportPath));
        emit exportFinished(m_exportPath, outcome.eRms, outcome.kind);
    });
    connect(m_exportJob, &BackgroundJobBase::failed, this, [this](const QString& message) {
        setStatus(tr("Export failed: %1").arg(message));
        emit exportFailed(m_exportPath, message);
    });
    connect(m_exportJob, &BackgroundJobBase::canceled, this, [this] { setStatus(tr("Export canceled.")); });
    connect(m_exportJob, &BackgroundJobBase::finished, this, &SkinningPanel::updateControls);
}

void SkinningPanel::setAnimation(std::shared_ptr<const LoadedAnimation> animation)
{
    m_job->cancel();       // its result, should it still arrive, counts as canceled
    m_exportJob->cancel(); // the file is still written; only the report is dropped
    m_animation = std::move(animation);
    m_segmentation.reset();
    m_segmentColors.clear();
    m_editor->setUndoStack(nullptr);
    m_editor->setBones({});
    m_session.reset();
    m_currentPose = 0;
    m_form->setSegmentCount(0);
    if (m_animation)
        m_editor->setLengthScale(double(glm::length(m_animation->bounds.max - m_animation->bounds.min)));
    showResult();
    setStatus(readyStatus());
}

void SkinningPanel::setSegmentation(const VertexLabeling* labeling, const std::vector<WheelColor>* colors)
{
    if (labeling && colors && colors->size() == labeling->count) {
        m_segmentation = *labeling;
        m_segmentColors = *colors;
    } else {
        m_segmentation.reset();
        m_segmentColors.clear();
    }
    m_form->setSegmentCount(m_segmentation ? m_segmentation->count : 0);
    if (!isRunning() && !m_session)
        setStatus(readyStatus());
    updateControls();
}

void SkinningPanel::onFormChanged()
{
    if (!isRunning() && !m_session)
        setStatus(readyStatus());
    updateControls();
}

bool SkinningPanel::hasUsableSegmentation() const
{
    return m_animation && m_segmentation && m_segmentation->count > 0 &&
           m_segmentation->labels.size() == m_animation->animation->vertexCount();
}

bool SkinningPanel::canFit() const
{
    if (!m_animation)
        return false;
    const SkinningChoices wanted = choices();
    if (wanted.boneSource == BoneSource::GivenCount)
        return std::size_t(wanted.boneCount) <= m_animation->animation->vertexCount();
    return hasUsableSegmentation();
}

QString SkinningPanel::readyStatus() const
{
    if (!m_animation)
        return tr("Open an animation (File ▸ Open Animation…) to fit a skinning to it.");
    const SkinningChoices wanted = choices();
    if (wanted.boneSource == BoneSource::GivenCount)
        return canFit() ? tr("Press Fit to segment into %1 bones and fit them to %2 poses.")
                              .arg(wanted.boneCount)
                              .arg(m_animation->animation->poseCount())
                        : tr("The animation has fewer vertices than %1 bones.").arg(wanted.boneCount);
    if (!hasUsableSegmentation())
        return tr("Segment the animation first (Segmentation panel): its segments become the bones.");
    return tr("Press Fit to fit %1 bones to %2 poses.")
        .arg(m_segmentation->count)
        .arg(m_animation->animation->poseCount());
}

void SkinningPanel::setCurrentPose(int pose)
{
    const bool moved = pose != m_currentPose;
    m_currentPose = pose;
    m_chart->setCurrentPose(pose);
    updateEditPose();
    // The heat map is the pose's. Only on a move: the window shows the pose again on
    // every displayChanged(), and calls this then.
    if (moved && m_view == SkinningView::ErrorHeatMap && m_session)
        refreshDisplay();
}

std::size_t SkinningPanel::heatMapPose() const
{
    const std::size_t poses = m_session ? m_session->approximation().size() : 0;
    return poses == 0 ? 0 : std::min(std::size_t(std::max(m_currentPose, 0)), poses - 1);
}

std::vector<double> SkinningPanel::heatMapErrors() const
{
    if (!m_session)
        return {};
    const std::size_t pose = heatMapPose();
    return poseVertexErrors(m_session->fit().original.at(pose), m_session->approximation().at(pose));
}

void SkinningPanel::setChoices(const SkinningChoices& choices)
{
    m_form->setChoices(choices);
    onFormChanged(); // the bone source or count decides whether Fit can run
}

SkinningChoices SkinningPanel::choices() const
{
    return m_form->choices();
}

void SkinningPanel::fit()
{
    if (!canFit() || isRunning())
        return;
    const SkinningChoices wanted = choices();
    const bool given = wanted.boneSource == BoneSource::GivenCount;
    m_fitAnimation = m_animation;
    SkinningBoneSource bones;
    if (given) {
        bones.count = std::size_t(wanted.boneCount);
        bones.segmenter = m_segmenterSettings;
    } else {
        bones.segmentation = BoneSegmentation{*m_segmentation, m_segmentColors, {}};
    }
    SkinningPipelineOptions options;
    options.fit = wanted.fitOptions();
    m_job->start([animation = m_animation->animation, bones = std::move(bones), options](const TaskControl& control) {
        return runSkinningFit(*animation, bones, options, control);
    });
    m_presenter->showStarted(given ? tr("Segmenting into %1 bones and fitting them…").arg(wanted.boneCount)
                                   : tr("Fitting %1 bones…").arg(m_segmentation->count));
    updateControls();
}

void SkinningPanel::exportGltf(const QString& path, double fps)
{
    if (!m_session || m_exportJob->isRunning())
        return;
    m_exportPath = path;
    const bool edited = m_session->isEdited();
    m_exportJob->start([fit = m_session->sharedFit(), model = m_session->model(),
                        file = std::filesystem::path(path.toStdU16String()), fps, morph = m_morphTargets->isChecked(),
                        step = m_interpolation->currentData().toInt() != 0, edited](const TaskControl&) {
        SkinExportOptions options;
        options.morphTargets = morph;
        options.stepInterpolation = step;
        // An edited model keeps its edits: its joints follow its own poses, not the original's.
        options.target = edited ? nullptr : &fit->original;
        const ExportedSkin report = exportSkinnedGltf(*model, file, fps, options);
        const std::string_view kind = skinExportKindName(report.kind);
        return ExportOutcome{measureSkinningError(fit->original, report.positions, model->restPose).eRms,
                             QString::fromUtf8(kind.data(), qsizetype(kind.size()))};
    });
    setStatus(tr("Exporting %1…").arg(path));
    updateControls();
}

void SkinningPanel::cancel()
{
    if (m_presenter->cancel())
        updateControls();
}

bool SkinningPanel::isRunning() const
{
    return m_job->isRunning();
}

void SkinningPanel::onFitSucceeded()
{
    m_session = std::make_unique<SkinningSession>(m_job->takeResult());
    connect(m_session.get(), &SkinningSession::modelChanged, this, &SkinningPanel::onModelChanged);
    m_editor->setBones(m_session->fit().boneColors);
    m_editor->setUndoStack(m_session->undoStack());
    const SkinningFitResult& result = m_session->fit().result;
    onFitEnded(tr("Done: %1 bones fitted to %2 poses in %3.")
                   .arg(result.model.boneCount())
                   .arg(result.model.poseCount())
                   .arg(milliseconds(result.times.totalMs)));
    emit resultChanged();
}

void SkinningPanel::onFitEnded(const QString& status)
{
    setStatus(status);
    showResult();
}

void SkinningPanel::onModelChanged()
{
    showResult();
}

void SkinningPanel::onApplyRequested(int bone, const BoneEdit& edit)
{
    if (!m_session || bone < 0)
        return;
    try {
        m_session->editBone(std::size_t(m_currentPose), std::size_t(bone), edit);
        setStatus(tr("Bone %1 moved at pose %2; later poses follow.").arg(bone).arg(m_currentPose));
    } catch (const std::exception& e) {
        setStatus(tr("Edit not applied: %1").arg(QString::fromStdString(e.what())));
    }
}

void SkinningPanel::setView(SkinningView view)
{
    m_viewBox->setCurrentIndex(m_viewBox->findData(int(view)));
}

void SkinningPanel::onViewChosen()
{
    m_view = SkinningView(m_viewBox->currentData().toInt());
    refreshDisplay();
}

std::optional<std::vector<glm::vec3>> SkinningPanel::shownPose(int pose) const
{
    if (m_view != SkinningView::Approximation || !m_session || pose < 0 ||
        std::size_t(pose) >= m_session->approximation().size())
        return std::nullopt;
    return m_session->approximatePose(std::size_t(pose));
}

std::shared_ptr<const SkinningModel> SkinningPanel::shownModel(int pose) const
{
    return shownPose(pose) ? m_session->model() : nullptr;
}

QString SkinningPanel::formatERms(double eRms)
{
    return QString::number(eRms, 'f', 4);
}

// The labels, chart, bone list and view of the session (or their empty state).
void SkinningPanel::showResult()
{
    if (!m_session) {
        m_error->setText(tr("No fit yet."));
        m_times->clear();
        m_chart->setErrors({});
        refreshDisplay();
        updateControls();
        return;
    }
    const SkinningFitResult& result = m_session->fit().result;
    const SkinningError& error = m_session->error();
    // E_RMS is in thousandths of a length unit (the thesis's scale) and the largest error
    // in length units: both named, so that the RMS does not look larger than the maximum.
    QString text = tr("E_RMS %1 thousandths of a unit (%2 ‰ of the model's diagonal) · largest vertex error %3 "
                      "units")
                       .arg(formatERms(error.eRms))
                       .arg(error.eRmsDiagonal, 0, 'g', 3)
                       .arg(error.maxDistance, 0, 'g', 3);
    if (m_session->isEdited())
        text += tr(" · edited; fitted E_RMS %1 thousandths").arg(formatERms(result.error.eRms));
    else if (result.weightCorrectionsKept || result.vertexCorrectionsKept)
        text += tr(" · E_RMS before corrections %1 thousandths").arg(formatERms(result.uncorrectedError.eRms));
    m_error->setText(text);
    m_times->setText(stageTimesText(result));
    if (m_session->isEdited())
        m_chart->setErrors(error.perPose, result.error.perPose);
    else
        m_chart->setErrors(error.perPose);
    refreshDisplay();
    updateControls();
}

void SkinningPanel::refreshDisplay()
{
    const bool heatMap = m_view == SkinningView::ErrorHeatMap && m_session;
    if (heatMap) {
        // The pose shown, on the scale of the largest error of any pose, so that colours
        // compare from pose to pose and a bone edit shows where and when it moved the mesh.
        const double largest = m_session->error().maxDistance;
        m_displayColors = heatMapRgba8(heatMapErrors(), largest);
        m_legend->setRange(largest, tr("length units, pose %1").arg(heatMapPose()));
    } else {
        m_displayColors.clear();
    }
    m_legend->setVisible(heatMap);
    emit displayChanged();
}

void SkinningPanel::updateEditPose()
{
    if (!m_session) {
        m_editor->setPose(m_currentPose, false, tr("Fit first: the bones of the fit can then be moved."));
        return;
    }
    const SkinningModel& model = *m_session->model();
    if (m_currentPose < 0 || std::size_t(m_currentPose) >= model.poseCount())
        m_editor->setPose(m_currentPose, false, tr("Pose %1 is not in the fit.").arg(m_currentPose));
    else if (std::size_t(m_currentPose) == model.restPose)
        m_editor->setPose(m_currentPose, false,
                          tr("Pose %1 is the rest pose: it has no bone transforms. Go to a later pose to edit it.")
                              .arg(m_currentPose));
    else if (model.chain == SkinningChain::RestToPose)
        m_editor->setPose(
            m_currentPose, true,
            tr("Edits apply to pose %1 only (a rest-to-pose fit does not chain poses).").arg(m_currentPose));
    else
        m_editor->setPose(m_currentPose, true);
}

void SkinningPanel::updateControls()
{
    const bool running = isRunning();
    m_form->setEnabled(m_animation != nullptr && !running);
    m_presenter->updateRow(canFit());
    m_viewBox->setEnabled(m_session != nullptr);
    m_editGroup->setEnabled(m_session != nullptr);
    m_export->setEnabled(m_session != nullptr && !m_exportJob->isRunning());
    updateEditPose();
}

void SkinningPanel::setStatus(const QString& text)
{
    m_status->setText(text);
}

// Ctrl+Z / Ctrl+Shift+Z inside the panel undo and redo pose edits: claiming the
// shortcut override keeps a window-wide shortcut on the same keys from taking them.
// Editors that undo their own text (the spin boxes) claim them first and keep them.
bool SkinningPanel::event(QEvent* event)
{
    if (event->type() == QEvent::ShortcutOverride && m_session) {
        const auto* key = static_cast<QKeyEvent*>(event);
        if (isUndoOrRedoKey(*key)) {
            event->accept();
            return true;
        }
    }
    return QWidget::event(event);
}

void SkinningPanel::keyPressEvent(QKeyEvent* event)
{
    if (m_session && applyUndoKey(*m_session->undoStack(), *event))
        return;
    QWidget::keyPressEvent(event);
}

} // namespace trimlab::ui
