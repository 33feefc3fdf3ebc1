#include "ui/skeleton/skeleton_panel.h"

#include "ui/common/run_cancel_row.h"
#include "ui/common/undo_buttons.h"
#include "ui/skeleton/skeleton_pose_command.h"

#include "ui/common/heat_map_legend.h"
#include "ui/common/job_presenter.h"
#include "ui/skeleton/skeleton_overlay.h"
#include "core/skeleton/skeleton_pose_edit.h"
#include "ui/skeleton/skeleton_pose_tool.h"
#include "ui/skeleton/skeleton_settings_form.h"
#include "core/skeleton/skeleton_stage_colors.h"
#include "ui/viewport/viewport_widget.h"

#include "core/skeleton/bone_names.h"
#include "core/skeleton/rigged_gltf.h"
#include "core/skeleton/skeleton_json.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

#include <glm/matrix.hpp>

#include <algorithm>
#include <filesystem>
#include <iterator>

namespace trimlab::ui {

namespace {

/// Pause after a change of the node count or root before the rig is re-selected, so that
/// stepping a spin box through several values runs once.
constexpr int kRerunDelayMs = 400;

QString seconds(double ms)
{
    return QString::number(ms * 1e-3, 'f', 3);
}

std::filesystem::path filePath(const QString& path)
{
    return std::filesystem::path(path.toStdU16String());
}

SkeletonPipelineOptions pipelineOptions(const SkeletonChoices& choices)
{
    SkeletonPipelineOptions options;
    options.extraction = choices.extraction;
    options.heatConstant = choices.heatConstant;
    return options;
}

} // namespace

SkeletonPanel::SkeletonPanel(QWidget* parent) : QWidget(parent)
{
    m_job = new BackgroundJob<std::shared_ptr<const SkeletonResult>>(this);
    m_form = new SkeletonSettingsForm;
    m_progress = new QProgressBar;
    m_progress->setObjectName(QStringLiteral("skeletonProgressBar"));
    m_status = new QLabel;
    m_status->setObjectName(QStringLiteral("skeletonStatusLabel"));
    m_status->setWordWrap(true);
    m_error = new QLabel;
    m_error->setObjectName(QStringLiteral("skeletonErrorLabel"));
    m_error->setWordWrap(true);
    m_error->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_error->setStyleSheet(QStringLiteral("color: #b00020; font-weight: bold;"));
    m_error->setVisible(false);
    m_rerunTimer = new QTimer(this);
    m_rerunTimer->setSingleShot(true);
    m_rerunTimer->setInterval(kRerunDelayMs);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_form);
    layout->addWidget(createRunRow());
    layout->addWidget(m_progress);
    layout->addWidget(m_status);
    layout->addWidget(m_error);
    layout->addWidget(createViewGroup());
    layout->addWidget(createPoseGroup());
    layout->addWidget(createExportRow());
    layout->addStretch();
    connect(m_form, &SkeletonSettingsForm::changed, this, [this] {
        emit choicesChanged();
        updateControls();
    });
    connect(m_form, &SkeletonSettingsForm::nodesOrRootChanged, this, [this] {
        if (m_result)
            m_rerunTimer->start();
    });
    connect(m_form, &SkeletonSettingsForm::skinningChanged, this, &SkeletonPanel::updatePose);
    connect(m_rerunTimer, &QTimer::timeout, this, &SkeletonPanel::run);
    connectJob();
    setScene(nullptr);
}

SkeletonPanel::~SkeletonPanel()
{
    if (m_viewport && m_toolInstalled)
        m_viewport->setTool(nullptr);
}

SkeletonOverlay* SkeletonPanel::overlay() const
{
    return m_overlay.data();
}

QWidget* SkeletonPanel::createRunRow()
{
    m_run = new QPushButton(tr("Run"));
    m_run->setObjectName(QStringLiteral("runSkeletonButton"));
    m_run->setToolTip(tr("Extract the skeleton of the mesh shown (contraction, simplification, refinement, "
                         "selection) and its bone-heat weights"));
    m_cancel = new QPushButton(tr("Cancel"));
    m_cancel->setObjectName(QStringLiteral("cancelSkeletonButton"));
    connect(m_run, &QPushButton::clicked, this, &SkeletonPanel::run);
    connect(m_cancel, &QPushButton::clicked, this, &SkeletonPanel::cancel);
    return runCancelRow(m_run, m_cancel);
}

QWidget* SkeletonPanel::createViewGroup()
{
    auto* group = new QGroupBox(tr("Result"));
    m_times = new QTableWidget(1, 6);
    m_times->setObjectName(QStringLiteral("skeletonTimesTable"));
    m_times->setHorizontalHeaderLabels(
        {tr("contraction"), tr("simplification"), tr("refinement"), tr("selection"), tr("weights"), tr("total")});
    m_times->setVerticalHeaderLabels({tr("s")});
    m_times->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_times->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_times->setMaximumHeight(70);
    m_times->setToolTip(tr("Seconds per stage of the last run (the paper's Table III); a re-selection shows only "
                           "selection and weights"));
    m_quality = createQualityTable();
    m_rigMeasures = new QLabel;
    m_rigMeasures->setObjectName(QStringLiteral("skeletonRigMeasuresLabel"));
    m_rigMeasures->setWordWrap(true);
    m_rigMeasures->setToolTip(tr("What posing needs of the rig: bones leaving the root, bones that turn back on "
                                 "their parent, and the weight vertices give to bones away from their own joint"));
    m_viewBox = new QComboBox;
    m_viewBox->setObjectName(QStringLiteral("skeletonViewComboBox"));
    m_viewBox->addItem(tr("Posed mesh"), int(SkeletonStageView::Pose));
    m_viewBox->addItem(tr("Contracted mesh (‖L·V′‖)"), int(SkeletonStageView::Contraction));
    m_viewBox->addItem(tr("Mesh–skeleton mapping"), int(SkeletonStageView::Mapping));
    m_viewBox->addItem(tr("Segmentation by joint"), int(SkeletonStageView::Segmentation));
    m_viewBox->addItem(tr("Weights of the selected bone"), int(SkeletonStageView::Weights));
    connect(m_viewBox, &QComboBox::currentIndexChanged, this, [this] {
        m_view = SkeletonStageView(m_viewBox->currentData().toInt());
        applyDisplay();
    });
    m_legend = new HeatMapLegend;
    m_legend->setVisible(false);
    auto* form = new QFormLayout;
    form->addRow(tr("Show"), m_viewBox);
    auto* layout = new QVBoxLayout(group);
    layout->addWidget(m_times);
    layout->addWidget(m_quality);
    layout->addWidget(m_rigMeasures);
    layout->addLayout(form);
    layout->addWidget(m_legend);
    return group;
}

// The evaluator's numbers (core/skeleton/skeleton_evaluation.h), curve and rig.
QTableWidget* SkeletonPanel::createQualityTable()
{
    auto* table = new QTableWidget(2, 6);
    table->setObjectName(QStringLiteral("skeletonQualityTable"));
    table->setHorizontalHeaderLabels(
        {tr("nodes in"), tr("samples in"), tr("leaving"), tr("centring"), tr("coverage"), tr("cycles")});
    table->setVerticalHeaderLabels({tr("curve"), tr("rig")});
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table->setMaximumHeight(95);
    table->setToolTip(tr("How good the skeleton is: nodes and edge samples inside the solid, edges that leave it, "
                         "mean asymmetry of the shortest chord through the samples (0 = centred), the farthest "
                         "vertex from any bone (x the bounding-box diagonal), and cycles / the mesh's genus"));
    return table;
}

void SkeletonPanel::showQuality()
{
    for (int row = 0; row < 2; ++row) {
        const SkeletonEvaluation* e = nullptr;
        if (m_result)
            e = row == 0 ? &m_result->curveQuality : &m_result->rigQuality;
        const QString values[6] = {
            e ? QStringLiteral("%1 %").arg(100.0 * e->nodesInside, 0, 'f', 1) : QStringLiteral("–"),
            e ? QStringLiteral("%1 %").arg(100.0 * e->samplesInside, 0, 'f', 1) : QStringLiteral("–"),
            e ? QString::number(e->edgesLeaving) : QStringLiteral("–"),
            e ? QString::number(e->meanAsymmetry, 'f', 3) : QStringLiteral("–"),
            e ? QString::number(e->maxCoverage, 'f', 3) : QStringLiteral("–"),
            e ? QStringLiteral("%1 / %2").arg(e->cycles).arg(e->meshGenus) : QStringLiteral("–"),
        };
        for (int column = 0; column < 6; ++column) {
            auto* item = new QTableWidgetItem(values[column]);
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            m_quality->setItem(row, column, item);
        }
    }
    m_rigMeasures->setText(
        m_result ? tr("Rig: %1").arg(QString::fromStdString(describeRigMeasures(m_result->rigMeasures))) : QString());
}

QWidget* SkeletonPanel::createPoseGroup()
{
    auto* group = new QGroupBox(tr("Pose"));
    m_poseGroup = group;
    m_boneList = new QListWidget;
    m_boneList->setObjectName(QStringLiteral("skeletonBoneList"));
    m_boneList->setMaximumHeight(120);
    connect(m_boneList, &QListWidget::currentRowChanged, this, &SkeletonPanel::selectBone);
    auto* angles = new QHBoxLayout;
    const char* names[3] = {"skeletonAngleXSpinBox", "skeletonAngleYSpinBox", "skeletonAngleZSpinBox"};
    const QString axes[3] = {QStringLiteral("x"), QStringLiteral("y"), QStringLiteral("z")};
    for (int i = 0; i < 3; ++i) {
        m_angles[i] = new QDoubleSpinBox;
        m_angles[i]->setObjectName(QString::fromLatin1(names[i]));
        m_angles[i]->setRange(-180.0, 180.0);
        m_angles[i]->setDecimals(1);
        m_angles[i]->setWrapping(true);
        m_angles[i]->setSuffix(QStringLiteral("°"));
        m_angles[i]->setPrefix(axes[i] + QStringLiteral(" "));
        m_angles[i]->setToolTip(
            tr("Rotation about the bone's local %1 axis (local y runs along the bone)").arg(axes[i]));
        connect(m_angles[i], &QDoubleSpinBox::valueChanged, this, &SkeletonPanel::onBoneAnglesEdited);
        angles->addWidget(m_angles[i]);
    }
    m_poseTool = new QCheckBox(tr("Pose with the mouse"));
    m_poseTool->setObjectName(QStringLiteral("skeletonPoseToolCheckBox"));
    m_poseTool->setToolTip(tr("Click near a bone in the view to select it, drag to turn it about its head; "
                              "elsewhere the mouse moves the camera"));
    connect(m_poseTool, &QCheckBox::toggled, this, &SkeletonPanel::setPoseToolEnabled);
    m_resetPose = new QPushButton(tr("Reset pose"));
    m_resetPose->setObjectName(QStringLiteral("resetSkeletonPoseButton"));
    connect(m_resetPose, &QPushButton::clicked, this, &SkeletonPanel::resetPose);
    m_poseUndoButtons =
        new UndoButtons(QStringLiteral("undoSkeletonPoseButton"), QStringLiteral("redoSkeletonPoseButton"), this);
    m_poseUndoButtons->setStack(&m_poseUndo);
    m_rootHere = new QPushButton(tr("Root here"));
    m_rootHere->setObjectName(QStringLiteral("skeletonRootHereButton"));
    m_rootHere->setToolTip(tr("Make the selected bone's head the root joint (selects the rig again)"));
    connect(m_rootHere, &QPushButton::clicked, this, [this] {
        if (m_result && m_selectedBone >= 0)
            m_form->pickRootJoint(m_result->rig.bones[std::size_t(m_selectedBone)].head);
    });
    // Two buttons a row, so that the panel fits a side dock without scrolling sideways.
    auto* buttons = new QGridLayout;
    buttons->addWidget(m_resetPose, 0, 0);
    buttons->addWidget(m_rootHere, 0, 1);
    buttons->addWidget(m_poseUndoButtons->undoButton(), 1, 0);
    buttons->addWidget(m_poseUndoButtons->redoButton(), 1, 1);
    auto* layout = new QVBoxLayout(group);
    layout->addWidget(m_boneList);
    layout->addLayout(angles);
    layout->addWidget(m_poseTool);
    layout->addLayout(buttons);
    return group;
}

QWidget* SkeletonPanel::createExportRow()
{
    m_exportGltf = new QPushButton(tr("Export rigged glTF…"));
    m_exportGltf->setObjectName(QStringLiteral("exportRiggedGltfButton"));
    m_exportJson = new QPushButton(tr("Export skeleton JSON…"));
    m_exportJson->setObjectName(QStringLiteral("exportSkeletonJsonButton"));
    connect(m_exportGltf, &QPushButton::clicked, this, &SkeletonPanel::exportGltfRequested);
    connect(m_exportJson, &QPushButton::clicked, this, &SkeletonPanel::exportJsonRequested);
    auto* row = new QWidget;
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_exportGltf);
    layout->addWidget(m_exportJson);
    return row;
}

void SkeletonPanel::connectJob()
{
    m_presenter =
        new JobPresenter(m_job, {m_run, m_cancel, m_progress, m_status}, JobPresenter::ProgressText::Percent, this);
    connect(m_job, &BackgroundJobBase::succeeded, this, &SkeletonPanel::onSucceeded);
    connect(m_job, &BackgroundJobBase::canceled, this,
            [this] { onEnded(m_result ? tr("Canceled; the previous skeleton is kept.") : tr("Canceled.")); });
    connect(m_job, &BackgroundJobBase::failed, this, [this](const QString& message) {
        m_error->setText(tr("Not extracted: %1").arg(message));
        m_error->setVisible(true);
        onEnded(m_result ? tr("The previous skeleton is kept.") : QString());
    });
}

void SkeletonPanel::setViewport(ViewportWidget* viewport)
{
    m_viewport = viewport;
    m_content = render::ContentPublisher(viewport->content(), render::ContentOwner::Skeleton);
    m_overlay = new SkeletonOverlay(viewport);
    m_tool = new SkeletonPoseTool(viewport, m_overlay, this);
    connect(m_tool, &SkeletonPoseTool::boneSelected, this, [this](int bone) {
        closeGesture(); // a press starts a drag: a step of its own
        selectBone(bone);
    });
    connect(m_tool, &SkeletonPoseTool::rotateRequested, this, &SkeletonPanel::rotateBone);
}

void SkeletonPanel::showPositions()
{
    m_content.showPose(m_shown);
}

void SkeletonPanel::setScene(std::shared_ptr<const LoadedScene> scene)
{
    m_job->cancel(); // a result that still arrives counts as canceled
    m_rerunTimer->stop();
    m_scene = std::move(scene);
    m_mesh.reset();
    m_unusable.clear();
    if (m_scene && m_scene->scene.objects.size() == 1) {
        const SceneObject& object = m_scene->scene.objects.front();
        m_mesh = std::shared_ptr<const TriangleMesh>(m_scene, &object.mesh);
        m_model = object.modelMatrix;
    } else if (m_scene) {
        m_unusable =
            tr("Skeleton extraction takes a scene of one object; this one has %1.").arg(m_scene->scene.objects.size());
    }
    m_result.reset();
    m_pose = {};
    m_poseUndo.clear();
    closeGesture();
    m_posed.clear();
    m_shown.clear();
    m_colors.clear();
    m_error->clear();
    m_error->setVisible(false);
    // The viewport dropped its pose and colours with the new scene; nothing to undo there.
    showResult();
    m_status->setText(readyStatus());
}

QString SkeletonPanel::readyStatus() const
{
    if (!m_scene)
        return tr("Open a closed mesh to extract its skeleton.");
    if (!m_unusable.isEmpty())
        return m_unusable;
    return tr("Press Run to extract the skeleton of %1 (%2 vertices).")
        .arg(QString::fromStdString(m_scene->displayName))
        .arg(m_mesh->vertexCount());
}

void SkeletonPanel::setChoices(const SkeletonChoices& choices)
{
    m_form->setChoices(choices);
}

SkeletonChoices SkeletonPanel::choices() const
{
    return m_form->choices();
}

void SkeletonPanel::run()
{
    m_rerunTimer->stop();
    if (!m_mesh || isRunning())
        return;
    m_runChoices = choices();
    const SkeletonPipelineOptions options = pipelineOptions(m_runChoices);
    const bool rigOnly = m_result && !m_resultChoices.needsContraction(m_runChoices);
    m_job->start([mesh = m_mesh, previous = rigOnly ? m_result : nullptr, options](const TaskControl& control) {
        return std::make_shared<const SkeletonResult>(previous ? rerunSkeletonRig(*mesh, *previous, options, control)
                                                               : runSkeletonPipeline(*mesh, options, control));
    });
    m_error->clear();
    m_error->setVisible(false);
    m_presenter->showStarted(
        rigOnly ? tr("Selecting %1 joints again and computing their weights…").arg(options.extraction.targetNodes)
                : tr("Extracting the skeleton…"));
    updateControls();
}

void SkeletonPanel::cancel()
{
    if (m_presenter->cancel())
        updateControls();
}

bool SkeletonPanel::isRunning() const
{
    return m_job->isRunning();
}

void SkeletonPanel::onSucceeded()
{
    m_result = m_job->takeResult();
    m_resultChoices = m_runChoices;
    m_pose = restPose(m_result->rig);
    m_poseUndo.clear(); // the steps turned the bones of the previous rig
    closeGesture();
    m_selectedBone = m_result->rig.bones.empty() ? -1 : 0;
    const SkeletonRig& rig = m_result->rig;
    onEnded(tr("Done: %1 joints, %2 bones (curve skeleton: %3 nodes) in %4 s%5.")
                .arg(rig.joints.size())
                .arg(rig.bones.size())
                .arg(m_result->extraction->curve.nodes.size())
                .arg(seconds(m_result->totalMs()))
                .arg(m_result->kind == SkeletonRunKind::RigOnly ? tr(" (selection and weights only)") : QString()));
    emit resultChanged();
}

void SkeletonPanel::onEnded(const QString& status)
{
    m_presenter->setStatus(status);
    showResult();
}

// The bone list, times, pose and views of the result (or their empty state).
void SkeletonPanel::showResult()
{
    {
        const QSignalBlocker blocker(m_boneList);
        m_boneList->clear();
        if (m_result) {
            const SkeletonRig& rig = m_result->rig;
            const std::vector<std::string> names = boneNames(rig);
            for (std::size_t b = 0; b < rig.bones.size(); ++b)
                m_boneList->addItem(tr("%1 (bone %2: joint %3 → %4)")
                                        .arg(QString::fromStdString(names[b]))
                                        .arg(b)
                                        .arg(rig.bones[b].head)
                                        .arg(rig.bones[b].tail));
        }
    }
    if (!m_result) {
        m_selectedBone = -1;
        if (m_overlay)
            m_overlay->setSkeleton({}, {}, -1, m_model);
        m_legend->setVisible(false);
        updateAngleBoxes(); // no bone: no angles (not the last run's)
    }
    showTimes();
    showQuality();
    if (m_result)
        selectBone(m_selectedBone);
    updatePose();
    applyDisplay();
    updateControls();
}

void SkeletonPanel::showTimes()
{
    for (int column = 0; column < m_times->columnCount(); ++column) {
        QString text = QStringLiteral("–");
        if (m_result) {
            const SkeletonStageTimes& t = m_result->times;
            const bool full = m_result->kind == SkeletonRunKind::Full;
            const double values[6] = {t.contractionMs, t.simplificationMs,  t.refinementMs,
                                      t.selectionMs,   m_result->weightsMs, m_result->totalMs()};
            if (full || column >= 3)
                text = seconds(values[column]);
        }
        auto* item = new QTableWidgetItem(text);
        item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        m_times->setItem(0, column, item);
    }
}

void SkeletonPanel::selectBone(int bone)
{
    const int count = m_result ? int(m_result->rig.bones.size()) : 0;
    m_selectedBone = bone >= 0 && bone < count ? bone : -1;
    {
        const QSignalBlocker blocker(m_boneList);
        m_boneList->setCurrentRow(m_selectedBone);
    }
    if (m_overlay)
        m_overlay->setSelectedBone(m_selectedBone);
    updateAngleBoxes();
    if (m_view == SkeletonStageView::Weights)
        applyDisplay();
    updateControls();
}

void SkeletonPanel::updateAngleBoxes()
{
    glm::dvec3 degrees(0.0);
    if (m_result && m_selectedBone >= 0)
        degrees =
            localDegreesOfBoneRotation(m_result->rig, m_selectedBone, m_pose.rotations[std::size_t(m_selectedBone)]);
    for (int i = 0; i < 3; ++i) {
        const QSignalBlocker blocker(m_angles[i]);
        m_angles[i]->setValue(degrees[i]);
    }
}

void SkeletonPanel::onBoneAnglesEdited()
{
    if (!m_result || m_selectedBone < 0)
        return;
    const auto* box = qobject_cast<const QDoubleSpinBox*>(sender());
    const int axis = int(std::find(std::begin(m_angles), std::end(m_angles), box) - std::begin(m_angles));
    const glm::dvec3 degrees(m_angles[0]->value(), m_angles[1]->value(), m_angles[2]->value());
    SkeletonPose after = m_pose;
    after.rotations[std::size_t(m_selectedBone)] = boneRotationFromLocalDegrees(m_result->rig, m_selectedBone, degrees);
    const QString axisName = axis < 3 ? QString(QChar(u'x' + axis)) : QString();
    pushPose(after, m_selectedBone, axis < 3 ? axis : kMouseGesture,
             tr("%1 angle of bone %2").arg(axisName).arg(m_selectedBone));
}

void SkeletonPanel::rotateBone(int bone, const glm::dvec3& worldAxis, double radians)
{
    if (!m_result || bone < 0 || bone >= int(m_result->rig.bones.size()))
        return;
    // Directions go from world to object space with the inverse of the model's linear part.
    const glm::dvec3 axis = glm::inverse(glm::dmat3(m_model)) * worldAxis;
    SkeletonPose after = m_pose;
    rotateBoneAboutAxis(m_result->rig, after, bone, axis, radians);
    pushPose(after, bone, kMouseGesture, tr("turn bone %1").arg(bone));
}

void SkeletonPanel::resetPose()
{
    if (!m_result)
        return;
    const SkeletonPose rest = restPose(m_result->rig);
    closeGesture();
    if (m_pose.rotations == rest.rotations && m_pose.rootTranslation == rest.rootTranslation)
        return; // nothing to reset: no step
    m_poseUndo.push(new SkeletonPoseCommand(
        tr("reset pose"), m_pose, rest, -1, -1, false,
        [this](const SkeletonPose& pose, int bone, bool refresh) { applyPose(pose, bone, refresh); }));
}

void SkeletonPanel::pushPose(const SkeletonPose& after, int bone, int source, const QString& text)
{
    if (m_gestureSource != source || m_gestureBone != bone) {
        m_gestureSource = source;
        m_gestureBone = bone;
        ++m_gesture;
    }
    m_poseUndo.push(new SkeletonPoseCommand(
        text, m_pose, after, bone, m_gesture, source != kMouseGesture,
        [this](const SkeletonPose& pose, int shownBone, bool refresh) { applyPose(pose, shownBone, refresh); }));
}

// The one place a pose change is shown: the commands call it on push, undo and redo.
void SkeletonPanel::applyPose(const SkeletonPose& pose, int bone, bool refreshAngles)
{
    if (!m_result)
        return;
    m_pose = pose;
    if (bone >= 0 && bone != m_selectedBone)
        selectBone(bone);
    else if (refreshAngles)
        updateAngleBoxes();
    updatePose();
}

// Ctrl+Z / Ctrl+Shift+Z inside the panel undo and redo pose steps; claiming the shortcut
// override keeps the window's Edit ▸ Undo on the same keys from taking them.
bool SkeletonPanel::event(QEvent* event)
{
    if (event->type() == QEvent::ShortcutOverride && m_result &&
        isUndoOrRedoKey(*static_cast<const QKeyEvent*>(event))) {
        event->accept();
        return true;
    }
    return QWidget::event(event);
}

void SkeletonPanel::keyPressEvent(QKeyEvent* event)
{
    if (m_result && applyUndoKey(m_poseUndo, *event)) {
        closeGesture();
        return;
    }
    QWidget::keyPressEvent(event);
}

// Skins the mesh to m_pose and shows it: the interactive path of every pose edit.
void SkeletonPanel::updatePose()
{
    if (!m_result || !m_mesh) {
        m_posed.clear();
        return;
    }
    QElapsedTimer timer;
    timer.start();
    const SkeletonRig& rig = m_result->rig;
    const std::vector<DualQuaternion> motions = boneMotions(rig, m_pose);
    skinPositions(m_mesh->positions, m_result->weights->weights(), motions, choices().skinning, m_posed);
    if (m_overlay) {
        std::vector<std::array<int, 2>> bones;
        bones.reserve(rig.bones.size());
        for (const Bone& bone : rig.bones)
            bones.push_back({bone.head, bone.tail});
        m_overlay->setSkeleton(posedJoints(rig, motions), std::move(bones), rig.root, m_model);
    }
    if (m_view == SkeletonStageView::Contraction)
        applyDisplay(); // the contracted mesh stays; only the overlay moved
    else if (m_viewport) {
        m_shown = m_posed;
        showPositions();
    }
    m_poseUpdateMs = double(timer.nsecsElapsed()) * 1e-6;
}

void SkeletonPanel::applyDisplay()
{
    m_legend->setVisible(false);
    if (!m_result || !m_mesh || !m_viewport)
        return;
    const SkeletonExtraction& extraction = *m_result->extraction;
    m_shown = m_posed;
    switch (m_view) {
    case SkeletonStageView::Pose:
        m_colors.clear();
        break;
    case SkeletonStageView::Contraction: {
        m_shown.assign(extraction.contracted.begin(), extraction.contracted.end());
        double largest = 0.0;
        m_colors = laplacianColors(extraction.laplacianMagnitude, largest);
        m_legend->setRange(largest, tr("‖L·V′‖"));
        m_legend->setVisible(true);
        break;
    }
    case SkeletonStageView::Mapping:
        m_colors = curveMappingColors(extraction.curve);
        break;
    case SkeletonStageView::Segmentation:
        m_colors = jointSegmentColors(m_result->rig);
        break;
    case SkeletonStageView::Weights:
        if (m_selectedBone >= 0) {
            m_colors = boneWeightColors(m_result->weights->boneWeightColumn(m_selectedBone));
            m_legend->setRange(1.0, tr("weight"));
            m_legend->setVisible(true);
        } else {
            m_colors = boneWeightColors(std::vector<double>(m_mesh->vertexCount(), 0.0));
        }
        break;
    }
    showPositions();
    m_content.showColors(m_colors);
}

void SkeletonPanel::setPoseToolEnabled(bool enabled)
{
    if (!m_viewport || !m_tool)
        return;
    {
        const QSignalBlocker blocker(m_poseTool);
        m_poseTool->setChecked(enabled);
    }
    if (enabled == m_toolInstalled)
        return;
    if (enabled) {
        emit poseToolToggled(true); // the window switches the brush off (and its tool) first
        m_viewport->setTool(m_tool);
    } else {
        m_viewport->setTool(nullptr);
        emit poseToolToggled(false);
    }
    m_toolInstalled = enabled;
}

void SkeletonPanel::poseToolTakenOver()
{
    m_toolInstalled = false;
    const QSignalBlocker blocker(m_poseTool);
    m_poseTool->setChecked(false);
}

bool SkeletonPanel::exportRiggedGltf(const QString& path, QString* error)
{
    try {
        if (!m_result || !m_mesh)
            throw std::runtime_error("there is no skeleton yet: press Run first");
        const SkeletonPose rest = restPose(m_result->rig);
        const bool posed = m_pose.rotations != rest.rotations || m_pose.rootTranslation != rest.rootTranslation;
        RiggedGltfOptions options;
        options.pose = posed ? &m_pose : nullptr;
        trimlab::exportRiggedGltf(*m_mesh, m_result->rig, m_result->weights->weights(), filePath(path), options);
        m_status->setText(tr("Exported %1.").arg(path));
        return true;
    } catch (const std::exception& e) {
        if (error)
            *error = QString::fromStdString(e.what());
        m_status->setText(tr("Export failed: %1").arg(QString::fromStdString(e.what())));
        return false;
    }
}

bool SkeletonPanel::exportSkeletonJson(const QString& path, QString* error)
{
    try {
        if (!m_result)
            throw std::runtime_error("there is no skeleton yet: press Run first");
        saveSkeletonJson(filePath(path), m_result->rig, &m_result->extraction->curve);
        m_status->setText(tr("Exported %1.").arg(path));
        return true;
    } catch (const std::exception& e) {
        if (error)
            *error = QString::fromStdString(e.what());
        m_status->setText(tr("Export failed: %1").arg(QString::fromStdString(e.what())));
        return false;
    }
}

void SkeletonPanel::updateControls()
{
    const bool running = isRunning();
    m_form->setEnabled(!running);
    m_presenter->updateRow(m_mesh != nullptr);
    m_viewBox->setEnabled(m_result != nullptr);
    m_poseGroup->setEnabled(m_result != nullptr);
    for (QDoubleSpinBox* box : m_angles)
        box->setEnabled(m_result != nullptr && m_selectedBone >= 0);
    m_rootHere->setEnabled(m_result != nullptr && m_selectedBone >= 0);
    m_exportGltf->setEnabled(m_result != nullptr);
    m_exportJson->setEnabled(m_result != nullptr);
}

} // namespace trimlab::ui
