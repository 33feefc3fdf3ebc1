#include "main_window.h"

#include "animation_opener.h"
#include "animation_settings_store.h"
#include "brush_panel.h"
#include "brush_settings_store.h"
#include "brush_tool.h"
#include "deformation_timeline_panel.h"
#include "design_session.h"
#include "design_workspace.h"
#include "history_exports.h"
#include "inspect_scene.h"
#include "mesh/mesh_validation.h"
#include "project_files.h"
#include "timeline/project_file.h"
#include "frame_stats_labels.h"
#include "frame_stats_panel.h"
#include "mesh_file_filter.h"
#include "method_group.h"
#include "method_timing_panel.h"
#include "open_animation_dialog.h"
#include "render_panel.h"
#include "render_settings_store.h"
#include "scene/demo_scenes.h"
#include "scene_loader.h"
#include "segmentation_panel.h"
#include "session_recovery.h"
#include "skeleton_panel.h"
#include "skeleton_settings_store.h"
#include "skinning_panel.h"
#include "timeline_panel.h"
#include "viewport_widget.h"

#include <QAction>
#include <QCloseEvent>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDir>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QRegularExpression>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>
#include <QUndoGroup>
#include <QVBoxLayout>

#include <glm/matrix.hpp>

namespace trimlab::ui {

namespace {

const QString kGeometryKey = QStringLiteral("window/geometry");
const QString kStateKey = QStringLiteral("window/state");
constexpr int kStatusMessageMs = 5000;

/// The first local file among dragged URLs, or "" when there is none.
QString firstLocalFile(const QMimeData* data)
{
    if (!data || !data->hasUrls())
        return {};
    for (const QUrl& url : data->urls()) {
        if (url.isLocalFile())
            return url.toLocalFile();
    }
    return {};
}

QString sceneLabel(const QString& source)
{
    if (isDemoSource(source.toStdString()))
        return source;
    return QFileInfo(source).fileName();
}

} // namespace

MainWindow::MainWindow(QWidget* parent)
    : MainWindow(std::make_unique<QSettings>(QSettings::NativeFormat, QSettings::UserScope, QStringLiteral("TrimLab"),
                                             QStringLiteral("TrimLab")),
                 parent)
{
}

MainWindow::MainWindow(const QString& settingsFile, QWidget* parent)
    : MainWindow(std::make_unique<QSettings>(settingsFile, QSettings::IniFormat), parent)
{
}

MainWindow::MainWindow(std::unique_ptr<QSettings> settings, QWidget* parent)
    : QMainWindow(parent), m_settings(std::move(settings))
{
    setObjectName(QStringLiteral("mainWindow"));
    setAcceptDrops(true);
    createCentralView();
    m_loader = new SceneLoader(this);
    m_animationOpener = new AnimationOpener(this);
    m_statsLabels = new FrameStatsLabels(statusBar());
    createDock();
    createStatsDock();
    createAnimationDocks();
    createDesignDocks();
    createSurfaceDock();
    createSkeletonDock();
    createInspectDock();
    createFileMenu();
    createEditMenu();
    createCreateMenu();
    createViewMenu();
    createHelpMenu();
    connectParts();
    connectAnimationParts();
    connectDesignParts();
    connectSurfaceParts();
    connectSkeletonParts();
    connectInspectParts();
    restoreSettings();
    updateTitle();
    QTimer::singleShot(0, this, &MainWindow::openDefaultIfNothingRequested);
    QTimer::singleShot(0, m_recovery, &SessionRecovery::offer);
}

MainWindow::~MainWindow() = default;

QString MainWindow::defaultSource()
{
    return QStringLiteral("demo:pushed-sphere");
}

void MainWindow::createCentralView()
{
    const QString glProblem = ViewportWidget::openGlProblem();
    if (glProblem.isEmpty()) {
        m_viewport = new ViewportWidget(this);
        m_viewport->setObjectName(QStringLiteral("viewport"));
        setCentralWidget(m_viewport);
        return;
    }
    // No usable OpenGL: a QOpenGLWidget in the window would break the window itself, so
    // the viewport stays detached (loading and the panel still work) and a text explains.
    m_detachedViewport = std::make_unique<ViewportWidget>();
    m_viewport = m_detachedViewport.get();
    m_viewport->setUnavailable(glProblem);
    auto* label = new QLabel(tr("The 3D view is unavailable.\n\n%1").arg(glProblem), this);
    label->setObjectName(QStringLiteral("viewportUnavailableLabel"));
    label->setAlignment(Qt::AlignCenter);
    label->setWordWrap(true);
    label->setMargin(24);
    setCentralWidget(label);
    QTimer::singleShot(0, this, [this, glProblem] { onRenderError(glProblem); });
}

void MainWindow::createDock()
{
    m_panel = new RenderPanel;
    auto* scroll = new QScrollArea;
    scroll->setWidget(m_panel);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    m_dock = new QDockWidget(tr("Render"), this);
    m_dock->setObjectName(QStringLiteral("renderDock"));
    m_dock->setAllowedAreas(Qt::LeftDockWidgetArea | Qt::RightDockWidgetArea);
    m_dock->setWidget(scroll);
    addDockWidget(Qt::RightDockWidgetArea, m_dock);
}

void MainWindow::createStatsDock()
{
    auto* content = new QWidget;
    auto* layout = new QVBoxLayout(content);
    m_statsPanel = new FrameStatsPanel(content);
    m_timingPanel = new MethodTimingPanel(m_viewport, content);
    layout->addWidget(m_statsPanel);
    layout->addWidget(m_timingPanel);
    layout->addStretch();
    auto* scroll = new QScrollArea;
    scroll->setWidget(content);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    m_statsDock = new QDockWidget(tr("Frame statistics"), this);
    m_statsDock->setObjectName(QStringLiteral("frameStatsDock"));
    m_statsDock->setAllowedAreas(Qt::LeftDockWidgetArea | Qt::RightDockWidgetArea);
    m_statsDock->setWidget(scroll);
    addDockWidget(Qt::RightDockWidgetArea, m_statsDock);
    splitDockWidget(m_dock, m_statsDock, Qt::Vertical);
}

void MainWindow::createAnimationDocks()
{
    m_timeline = new TimelinePanel;
    m_timelineDock = new QDockWidget(tr("Timeline"), this);
    m_timelineDock->setObjectName(QStringLiteral("timelineDock"));
    m_timelineDock->setAllowedAreas(Qt::BottomDockWidgetArea | Qt::TopDockWidgetArea);
    m_timelineDock->setWidget(m_timeline);
    addDockWidget(Qt::BottomDockWidgetArea, m_timelineDock);
    m_timelineDock->hide(); // shown while an animation is open

    m_segmentation = new SegmentationPanel;
    auto* scroll = new QScrollArea;
    scroll->setWidget(m_segmentation);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    m_segmentationDock = new QDockWidget(tr("Segmentation"), this);
    m_segmentationDock->setObjectName(QStringLiteral("segmentationDock"));
    m_segmentationDock->setAllowedAreas(Qt::LeftDockWidgetArea | Qt::RightDockWidgetArea);
    m_segmentationDock->setWidget(scroll);
    addDockWidget(Qt::RightDockWidgetArea, m_segmentationDock);
    tabifyDockWidget(m_dock, m_segmentationDock);
    m_dock->raise();

    m_skinning = new SkinningPanel;
    auto* skinningScroll = new QScrollArea;
    skinningScroll->setWidget(m_skinning);
    skinningScroll->setWidgetResizable(true);
    skinningScroll->setFrameShape(QFrame::NoFrame);
    m_skinningDock = new QDockWidget(tr("Skinning"), this);
    m_skinningDock->setObjectName(QStringLiteral("skinningDock"));
    m_skinningDock->setAllowedAreas(Qt::LeftDockWidgetArea | Qt::RightDockWidgetArea);
    m_skinningDock->setWidget(skinningScroll);
    addDockWidget(Qt::RightDockWidgetArea, m_skinningDock);
    tabifyDockWidget(m_segmentationDock, m_skinningDock);
    m_skinningDock->hide(); // shown while an animation is open
}

void MainWindow::createFileMenu()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* open = file->addAction(tr("&Open…"), this, &MainWindow::showOpenDialog);
    open->setShortcut(QKeySequence::Open);
    QMenu* demos = file->addMenu(tr("Open &Demo"));
    for (const std::string& name : demoSceneNames()) {
        const QString source = QString::fromStdString(std::string(kDemoPrefix) + name);
        QAction* action = demos->addAction(QString::fromStdString(name), this, [this, source] { openSource(source); });
        action->setStatusTip(QString::fromStdString(std::string(demoSceneDescription(name))));
    }
    m_recentMenu = file->addMenu(tr("Open &Recent"));
    QAction* addObject = file->addAction(tr("Add O&bject…"), this, &MainWindow::showAddObjectDialog);
    addObject->setObjectName(QStringLiteral("addObjectAction"));
    addObject->setStatusTip(tr("Load a mesh file into the scene shown as one more object (CSG, collisions)"));
    file->addSeparator();
    QAction* openAnimation = file->addAction(tr("Open &Animation…"), this, &MainWindow::showOpenAnimationDialog);
    openAnimation->setShortcut(QKeySequence(tr("Ctrl+Shift+O")));
    m_recentAnimationMenu = file->addMenu(tr("Open Recent A&nimation"));
    file->addSeparator();
    QAction* exportImage = file->addAction(tr("&Export Image…"), this, &MainWindow::showExportDialog);
    exportImage->setShortcut(QKeySequence(tr("Ctrl+E")));
    file->addSeparator();
    createDesignFileActions(file);
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);
    quit->setMenuRole(QAction::QuitRole);
}

void MainWindow::rebuildRecentMenu()
{
    m_recentMenu->clear();
    for (const QString& path : m_recent.paths())
        m_recentMenu->addAction(path, this, [this, path] { openRecent(path); });
    if (m_recent.paths().isEmpty()) {
        m_recentMenu->addAction(tr("(none)"))->setEnabled(false);
        return;
    }
    m_recentMenu->addSeparator();
    m_recentMenu->addAction(tr("Clear List"), this, [this] {
        for (const QString& path : m_recent.paths())
            m_recent.remove(path);
        m_recent.save(*m_settings);
        rebuildRecentMenu();
    });
}

void MainWindow::rebuildRecentAnimationMenu()
{
    m_recentAnimationMenu->clear();
    for (const QString& path : m_recentAnimations.paths())
        m_recentAnimationMenu->addAction(path, this, [this, path] { openRecentAnimation(path); });
    if (m_recentAnimations.paths().isEmpty()) {
        m_recentAnimationMenu->addAction(tr("(none)"))->setEnabled(false);
        return;
    }
    m_recentAnimationMenu->addSeparator();
    m_recentAnimationMenu->addAction(tr("Clear List"), this, [this] {
        for (const QString& path : m_recentAnimations.paths())
            m_recentAnimations.remove(path);
        m_recentAnimations.save(*m_settings);
        rebuildRecentAnimationMenu();
    });
}

void MainWindow::createViewMenu()
{
    m_viewMenu = menuBar()->addMenu(tr("&View"));
    // Single-key shortcuts act only while the viewport has focus (never while typing).
    QAction* fit = m_viewMenu->addAction(tr("&Fit to View"), m_viewport, &ViewportWidget::fitToView);
    fit->setShortcut(QKeySequence(Qt::Key_F));
    fit->setShortcutContext(Qt::WidgetShortcut);
    m_viewport->addAction(fit);
    QAction* reset = m_viewMenu->addAction(tr("&Reset View"), m_viewport, &ViewportWidget::resetView);
    reset->setShortcut(QKeySequence(Qt::Key_Home));
    reset->setShortcutContext(Qt::WidgetShortcut);
    m_viewport->addAction(reset);
    m_viewMenu->addSeparator();
    QAction* panel = m_dock->toggleViewAction();
    panel->setText(tr("Render &Panel"));
    m_viewMenu->addAction(panel);
    QAction* scenePanel = m_sceneDock->toggleViewAction();
    scenePanel->setText(tr("S&cene Panel"));
    m_viewMenu->addAction(scenePanel);
    QAction* statistics = m_statsDock->toggleViewAction();
    statistics->setText(tr("Frame &Statistics"));
    m_viewMenu->addAction(statistics);
    QAction* segmentation = m_segmentationDock->toggleViewAction();
    segmentation->setText(tr("Se&gmentation Panel"));
    m_viewMenu->addAction(segmentation);
    QAction* skinning = m_skinningDock->toggleViewAction();
    skinning->setText(tr("S&kinning Panel"));
    m_viewMenu->addAction(skinning);
    QAction* skeleton = m_skeletonDock->toggleViewAction();
    skeleton->setText(tr("Ske&leton Panel"));
    m_viewMenu->addAction(skeleton);
    QAction* timeline = m_timelineDock->toggleViewAction();
    timeline->setText(tr("&Timeline"));
    m_viewMenu->addAction(timeline);
    QAction* brush = m_brushDock->toggleViewAction();
    brush->setText(tr("&Brush Panel"));
    m_viewMenu->addAction(brush);
    QAction* deformation = m_deformationDock->toggleViewAction();
    deformation->setText(tr("&Deformation Timeline"));
    m_viewMenu->addAction(deformation);
}

void MainWindow::createHelpMenu()
{
    QMenu* help = menuBar()->addMenu(tr("&Help"));
    QAction* about = help->addAction(tr("&About TrimLab"), this, &MainWindow::showAbout);
    about->setMenuRole(QAction::AboutRole);
}

void MainWindow::connectParts()
{
    connect(m_loader, &SceneLoader::loaded, this, &MainWindow::onSceneLoaded);
    connect(m_loader, &SceneLoader::failed, this, &MainWindow::onLoadFailed);
    connect(m_loader, &SceneLoader::canceled, this, [this](const QString& source) {
        statusBar()->showMessage(tr("Opening %1 canceled.").arg(sceneLabel(source)), kStatusMessageMs);
    });
    connect(m_panel, &RenderPanel::renderChoicesChanged, this, &MainWindow::applyRenderChoices);
    connect(m_panel, &RenderPanel::viewDirectionRequested, this, [this] {
        const Camera camera = m_viewport->camera();
        m_panel->setClipNormal(camera.target - camera.eye);
    });
    connect(m_viewport, &ViewportWidget::frameRendered, m_statsLabels, &FrameStatsLabels::showStats);
    connect(m_viewport, &ViewportWidget::frameRendered, this, &MainWindow::showFrameStatistics);
    connect(m_viewport, &ViewportWidget::framePixelSizeChanged, this, &MainWindow::refreshMemoryEstimate);
    connect(m_statsPanel, &FrameStatsPanel::methodRequested, this, &MainWindow::chooseMethod);
    connect(m_statsPanel, &FrameStatsPanel::kRequested, this, &MainWindow::chooseK);
    // Queued: the viewport reports from inside paintGL, where no dialog may open.
    connect(m_viewport, &ViewportWidget::renderError, this, &MainWindow::onRenderError, Qt::QueuedConnection);
    // Not an error dialog: the view still shows a correct image, rendered another way.
    const auto showNotice = [this](const QString& message) { statusBar()->showMessage(message, 4 * kStatusMessageMs); };
    connect(m_viewport, &ViewportWidget::memoryFallback, this, showNotice, Qt::QueuedConnection);
    // Nor is a GPU reset: the view re-creates its context and shows the same frame.
    connect(m_viewport, &ViewportWidget::contextLost, this, showNotice, Qt::QueuedConnection);
}

void MainWindow::connectAnimationParts()
{
    connect(m_animationOpener, &AnimationOpener::loaded, this, &MainWindow::onAnimationLoaded);
    connect(m_animationOpener, &AnimationOpener::failed, this, &MainWindow::onLoadFailed);
    connect(m_animationOpener, &AnimationOpener::canceled, this, [this](const QString& source) {
        statusBar()->showMessage(tr("Opening %1 canceled.").arg(sceneLabel(source)), kStatusMessageMs);
    });
    connect(m_timeline, &TimelinePanel::poseChanged, this, &MainWindow::showPose);
    connect(m_timeline, &TimelinePanel::playbackChoicesChanged, this, [this] {
        savePlaybackChoices(*m_settings, {m_timeline->fps(), m_timeline->loops()});
    });
    connect(m_segmentation, &SegmentationPanel::displayColorsChanged, this, &MainWindow::showSegmentColors);
    connect(m_segmentation, &SegmentationPanel::choicesChanged, this,
            [this] { saveSegmentationChoices(*m_settings, m_segmentation->choices()); });
    connect(m_segmentation, &SegmentationPanel::streamStarted, this, [this] {
        m_timeline->setPose(0);
        m_timeline->play();
    });
    connect(m_segmentation, &SegmentationPanel::exportRequested, this, &MainWindow::showExportSegmentationDialog);
    connect(m_segmentation, &SegmentationPanel::displayColorsChanged, this, &MainWindow::passSegmentationToSkinning);
    connect(m_segmentation, &SegmentationPanel::choicesChanged, this, &MainWindow::passSegmentationToSkinning);
    connect(m_skinning, &SkinningPanel::displayChanged, this, [this] {
        showPose(m_timeline->pose());
        showSegmentColors();
    });
    connect(m_skinning, &SkinningPanel::exportRequested, this, &MainWindow::showExportSkinningDialog);
    connect(m_skinning, &SkinningPanel::exportFinished, this, [this](const QString& path, double eRms, const QString& kind) {
        showMessage(QMessageBox::Information, tr("Export Skinning"), tr("Saved %1").arg(path),
                    tr("E_RMS of the exported file against the original animation: %1 (%2)")
                        .arg(SkinningPanel::formatERms(eRms), kind));
    });
    connect(m_skinning, &SkinningPanel::exportFailed, this, [this](const QString& path, const QString& message) {
        showMessage(QMessageBox::Warning, tr("Export Skinning"), tr("%1 was not saved.").arg(path), message);
    });
}

void MainWindow::restoreSettings()
{
    m_recent.load(*m_settings);
    rebuildRecentMenu();
    m_recentAnimations.load(*m_settings);
    rebuildRecentAnimationMenu();
    m_segmentation->setChoices(loadSegmentationChoices(*m_settings));
    m_skeleton->setChoices(loadSkeletonChoices(*m_settings));
    const PlaybackChoices playback = loadPlaybackChoices(*m_settings);
    m_timeline->setPlaybackChoices(playback.fps, playback.loop);
    m_panel->setRenderChoices(loadRenderChoices(*m_settings));
    applyRenderChoices();
    const BrushChoices brush = loadBrushChoices(*m_settings);
    m_brushPanel->setChoices(brush);
    m_design->setBrushSettings(m_brushPanel->settings());
    m_brushAction->setChecked(brush.toolEnabled);
    m_deformationPanel->setFps(m_settings->value(QStringLiteral("design/fps"), 12).toInt());
    m_exports->setFps(m_deformationPanel->fps());
    if (!restoreGeometry(m_settings->value(kGeometryKey).toByteArray()))
        resize(1100, 720);
    if (!restoreState(m_settings->value(kStateKey).toByteArray())) {
        resizeDocks({m_dock}, {380}, Qt::Horizontal);
        resizeDocks({m_dock, m_statsDock}, {440, 300}, Qt::Vertical); // the Render panel is the taller
    }
    m_timelineDock->hide(); // until an animation is opened
    m_skinningDock->hide();
    m_deformationDock->hide(); // until a deformation history starts
}

void MainWindow::saveWindowState()
{
    m_settings->setValue(kGeometryKey, saveGeometry());
    m_settings->setValue(kStateKey, saveState());
    m_settings->sync();
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (!m_projectFiles->maybeSave()) {
        event->ignore();
        return;
    }
    saveWindowState();
    QMainWindow::closeEvent(event);
}

void MainWindow::openSource(const QString& source)
{
    if (!m_projectFiles->maybeSave())
        return;
    m_openRequested = true;
    if (ProjectFiles::isProjectPath(source)) {
        m_loader->cancel();
        m_animationOpener->cancel();
        statusBar()->showMessage(tr("Opening project %1…").arg(sceneLabel(source)));
        m_projectFiles->open(source);
        return;
    }
    m_animationOpener->cancel(); // the newest request wins
    m_objectLoader->cancel();
    statusBar()->showMessage(tr("Opening %1…").arg(sceneLabel(source)));
    m_loader->load(source);
}

void MainWindow::openAnimation(const QString& source)
{
    if (!m_projectFiles->maybeSave())
        return;
    m_openRequested = true;
    m_loader->cancel(); // the newest request wins
    statusBar()->showMessage(tr("Opening animation %1…").arg(sceneLabel(source)));
    m_animationOpener->open(source);
}

void MainWindow::openDefaultIfNothingRequested()
{
    if (!m_openRequested)
        openSource(defaultSource());
}

bool MainWindow::isLoading() const
{
    return m_loader->isLoading() || m_objectLoader->isLoading() || m_animationOpener->isLoading() ||
           m_projectFiles->isOpening() ||
           m_exports->isReplaying();
}

void MainWindow::openRecent(const QString& path)
{
    if (QFileInfo::exists(path)) {
        openSource(path);
        return;
    }
    m_recent.remove(path);
    m_recent.save(*m_settings);
    rebuildRecentMenu();
    showMessage(QMessageBox::Warning, tr("File not found"), tr("“%1” no longer exists.").arg(path),
                tr("It was removed from the recent files."));
}

void MainWindow::openRecentAnimation(const QString& path)
{
    // A pattern (dir/mesh_*.obj, dir/mesh_%04d.obj) is not a file; its folder must exist.
    const QFileInfo info(path);
    const bool pattern = path.contains(QRegularExpression(QStringLiteral("[*?%]")));
    if (info.exists() || (pattern && info.dir().exists())) {
        openAnimation(path);
        return;
    }
    m_recentAnimations.remove(path);
    m_recentAnimations.save(*m_settings);
    rebuildRecentAnimationMenu();
    showMessage(QMessageBox::Warning, tr("Animation not found"), tr("“%1” no longer exists.").arg(path),
                tr("It was removed from the recent animations."));
}

void MainWindow::showOpenAnimationDialog()
{
    const QString source = OpenAnimationDialog::getSource(this, loadLastDirectory(*m_settings));
    if (source.isEmpty())
        return;
    const QFileInfo info(source);
    saveLastDirectory(*m_settings, info.isDir() ? info.absoluteFilePath() : info.absolutePath());
    openAnimation(source);
}

void MainWindow::showOpenDialog()
{
    // The first filter offers meshes and projects together; the project filter follows it.
    QString filter = meshFileDialogFilter();
    const qsizetype paren = filter.indexOf(QLatin1Char('('));
    filter.insert(paren + 1, QStringLiteral("*.%1 ").arg(QLatin1String(ProjectFiles::kSuffix)));
    filter.replace(0, paren, tr("Meshes and projects "));
    filter.insert(filter.indexOf(QStringLiteral(";;")) + 2, ProjectFiles::dialogFilter() + QStringLiteral(";;"));
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Mesh or Project"), loadLastDirectory(*m_settings),
                                                      filter);
    if (path.isEmpty())
        return;
    saveLastDirectory(*m_settings, QFileInfo(path).absolutePath());
    openSource(path);
}

void MainWindow::onSceneLoaded(std::shared_ptr<const LoadedScene> loaded)
{
    clearAnimation();
    m_design->endSession(); // before the viewport takes the new scene
    const Bounds bounds = loaded->scene.worldBounds();
    showScene(std::move(loaded), bounds);
    startDesignSession();
    const QString source = QString::fromStdString(m_scene->source);
    if (!isDemoSource(m_scene->source)) {
        m_recent.add(source);
        m_recent.save(*m_settings);
        rebuildRecentMenu();
    }
    statusBar()->showMessage(tr("%1: %2 triangles%3")
                                 .arg(QString::fromStdString(m_scene->displayName))
                                 .arg(m_scene->scene.triangleCount())
                                 .arg(m_scene->trimmable() ? QString() : tr(" — trim modes unavailable")),
                             kStatusMessageMs);
    emit sceneLoaded(source);
}

void MainWindow::onAnimationLoaded(std::shared_ptr<const LoadedAnimation> loaded)
{
    m_design->endSession(); // an animation's poses are not a deformation history
    m_animation = std::move(loaded);
    showScene(m_animation->restScene, m_animation->bounds);
    m_skeleton->setScene(nullptr); // the timeline drives the poses of an animation
    m_viewport->setViewBounds(m_animation->bounds); // no pose may cross the far plane
    const MeshAnimation& animation = *m_animation->animation;
    QStringList names;
    for (std::size_t pose = 0; pose < animation.poseCount(); ++pose)
        names << (pose < animation.poseNames.size() ? QString::fromStdString(animation.poseNames[pose])
                                                    : tr("pose %1").arg(pose));
    m_timeline->setPoses(names);
    m_segmentation->setAnimation(m_animation);
    m_skinning->setAnimation(m_animation);
    passSegmentationToSkinning();
    m_timelineDock->show();
    m_skinningDock->show();
    m_segmentationDock->show();
    m_segmentationDock->raise();
    const QString source = QString::fromStdString(m_scene->source);
    m_recentAnimations.add(source);
    m_recentAnimations.save(*m_settings);
    rebuildRecentAnimationMenu();
    statusBar()->showMessage(tr("%1: %2 poses, %3 vertices, %4 triangles%5")
                                 .arg(QString::fromStdString(m_scene->displayName))
                                 .arg(animation.poseCount())
                                 .arg(animation.vertexCount())
                                 .arg(animation.triangleCount())
                                 .arg(m_scene->trimmable() ? QString() : tr(" — trim modes unavailable")),
                             kStatusMessageMs);
    emit animationLoaded(source);
}

// What a mesh and an animation's rest pose share: the scene, the trim controls (with
// `bounds` for the clip offset) and the title.
void MainWindow::showScene(std::shared_ptr<const LoadedScene> loaded, const Bounds& bounds)
{
    m_scene = std::move(loaded);
    m_panel->setSceneInfo(bounds, m_scene->trimmable(), QString::fromStdString(m_scene->trimUnavailableReason()));
    m_viewport->setScene(std::shared_ptr<const Scene>(m_scene, &m_scene->scene));
    m_skeleton->setScene(m_scene); // after the viewport: its result never meets another mesh
    m_inspect->reset(m_scene); // no CSG, transforms of the new scene, a clean scene undo stack
    applyRenderChoices();
    updateSceneEditability();
    updateTitle();
}

void MainWindow::clearAnimation()
{
    if (!m_animation)
        return;
    m_animation.reset();
    m_timeline->setPoses({});
    m_segmentation->setAnimation(nullptr);
    m_skinning->setAnimation(nullptr);
    m_timelineDock->hide();
    m_skinningDock->hide();
    updateSceneEditability();
}

void MainWindow::showPose(int pose)
{
    if (!m_animation || pose < 0 || std::size_t(pose) >= m_animation->animation->poseCount())
        return;
    if (const std::optional<std::vector<glm::vec3>> skinned = m_skinning->shownPose(pose))
        m_viewport->showPose(*skinned);
    else
        m_viewport->showPose(m_animation->animation->poses[std::size_t(pose)]);
    m_segmentation->setCurrentPose(pose);
    m_skinning->setCurrentPose(pose);
}

// The skinning error heat map, while shown, takes the place of the segment colors.
void MainWindow::showSegmentColors()
{
    if (!m_animation)
        return;
    const std::vector<std::uint32_t>& heatMap = m_skinning->displayColors();
    m_viewport->setVertexColors(heatMap.empty() ? m_segmentation->displayColors() : heatMap);
}

// The Skinning panel's bones: the segmentation shown, unless it changes per pose
// (variable mode); a given bone count segments with the Segmentation panel's settings.
void MainWindow::passSegmentationToSkinning()
{
    const bool variable = m_segmentation->choices().mode == SegmentationMode::Variable;
    m_skinning->setSegmentation(variable ? nullptr : m_segmentation->shownLabeling(),
                                variable ? nullptr : m_segmentation->shownColors());
    m_skinning->setSegmenterSettings(m_segmentation->choices().segmenterSettings());
}

void MainWindow::onLoadFailed(const QString& source, const QString& message)
{
    statusBar()->clearMessage();
    showMessage(QMessageBox::Critical, tr("Could not open"), tr("Could not open “%1”.").arg(sceneLabel(source)),
                message);
    emit sceneLoadFailed(source, message);
}

void MainWindow::onRenderError(const QString& message)
{
    m_statsLabels->clear();
    m_statsPanel->clear();
    showMessage(QMessageBox::Critical, tr("OpenGL problem"), tr("The viewport cannot render."), message);
}

void MainWindow::applyRenderChoices()
{
    const RenderChoices choices = m_panel->renderChoices();
    saveRenderChoices(*m_settings, choices);
    TrimSettings effective = choices.trim;
    effective.csg = m_inspect->csg(); // the Scene panel's: it belongs to the scene, not to the saved choices
    // The winding index is undefined for open or inconsistently oriented surfaces.
    effective.trimEnabled = effective.trimEnabled && m_panel->sceneTrimmable();
    m_viewport->setTrimSettings(effective);
    m_design->setRenderMode(choices.dynamicRules, choices.trim.rule, effective.trimEnabled);
    m_viewport->setMethod(choices.method);
    m_viewport->setMethodParameters(choices.methodParameters());
    refreshMemoryEstimate();
}

void MainWindow::refreshMemoryEstimate()
{
    m_panel->setMemoryEstimate(m_viewport->memoryEstimate());
}

void MainWindow::showFrameStatistics()
{
    if (const auto& frame = m_viewport->lastFrame()) {
        m_statsPanel->showFrame(*frame);
        m_statsLabels->showHighlights(frame->settings.highlight, frame->stats.counts);
    }
    refreshMemoryEstimate();
}

void MainWindow::chooseMethod(render::FragmentMethodKind method)
{
    RenderChoices choices = m_panel->renderChoices();
    choices.method = method;
    m_panel->setRenderChoices(choices);
    applyRenderChoices();
    statusBar()->showMessage(tr("Switched to %1.").arg(methodDisplayName(render::methodInfo(method))), kStatusMessageMs);
}

void MainWindow::chooseK(int k)
{
    RenderChoices choices = m_panel->renderChoices();
    choices.k = k;
    m_panel->setRenderChoices(choices);
    applyRenderChoices();
    statusBar()->showMessage(tr("k raised to %1.").arg(k), kStatusMessageMs);
}

bool MainWindow::exportImage(const QString& path, QString* error)
{
    const QImage image = m_viewport->readColorImage();
    QString reason;
    if (image.isNull())
        reason = tr("Nothing has been rendered yet.");
    else if (!image.convertToFormat(QImage::Format_RGB32).save(path, "PNG"))
        reason = tr("Could not write “%1”.").arg(path);
    if (error)
        *error = reason;
    return reason.isEmpty();
}

void MainWindow::showExportDialog()
{
    const QString name = m_scene ? QString::fromStdString(m_scene->displayName) : QStringLiteral("trimlab");
    const QString suggested = loadLastDirectory(*m_settings) + QLatin1Char('/') + QFileInfo(name).completeBaseName() +
                              QStringLiteral(".png");
    QString path = QFileDialog::getSaveFileName(this, tr("Export Image"), suggested, tr("PNG image (*.png)"));
    if (path.isEmpty())
        return;
    if (!path.endsWith(QStringLiteral(".png"), Qt::CaseInsensitive))
        path += QStringLiteral(".png");
    saveLastDirectory(*m_settings, QFileInfo(path).absolutePath());
    QString error;
    if (exportImage(path, &error))
        statusBar()->showMessage(tr("Saved %1").arg(path), kStatusMessageMs);
    else
        showMessage(QMessageBox::Warning, tr("Export Image"), tr("The image was not saved."), error);
}

void MainWindow::showExportSegmentationDialog()
{
    const QStringList filters{tr("Segmentation JSON (*.json)"), tr("Per-vertex labels CSV (*.csv)"),
                              tr("glTF with segment colors (*.gltf)")};
    const QString name = m_scene ? QFileInfo(QString::fromStdString(m_scene->displayName)).completeBaseName()
                                 : QStringLiteral("animation");
    const QString suggested = loadLastDirectory(*m_settings) + QLatin1Char('/') + name + QStringLiteral("-segments.json");
    QString filter = filters.front();
    QString path = QFileDialog::getSaveFileName(this, tr("Export Segmentation"), suggested,
                                                filters.join(QStringLiteral(";;")), &filter);
    if (path.isEmpty())
        return;
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix != QStringLiteral("json") && suffix != QStringLiteral("csv") && suffix != QStringLiteral("gltf"))
        path += QRegularExpression(QStringLiteral("\\*(\\.\\w+)")).match(filter).captured(1);
    saveLastDirectory(*m_settings, QFileInfo(path).absolutePath());
    QString error;
    if (m_segmentation->exportSegmentation(path, &error))
        statusBar()->showMessage(tr("Saved %1").arg(path), kStatusMessageMs);
    else
        showMessage(QMessageBox::Warning, tr("Export Segmentation"), tr("The segmentation was not saved."), error);
}

void MainWindow::showExportSkinningDialog()
{
    const QStringList filters{tr("glTF (*.gltf)"), tr("Binary glTF (*.glb)")};
    const QString name = m_scene ? QFileInfo(QString::fromStdString(m_scene->displayName)).completeBaseName()
                                 : QStringLiteral("animation");
    const QString suggested = loadLastDirectory(*m_settings) + QLatin1Char('/') + name + QStringLiteral("-skinned.gltf");
    QString filter = filters.front();
    QString path = QFileDialog::getSaveFileName(this, tr("Export Skinning"), suggested,
                                                filters.join(QStringLiteral(";;")), &filter);
    if (path.isEmpty())
        return;
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix != QStringLiteral("gltf") && suffix != QStringLiteral("glb"))
        path += QRegularExpression(QStringLiteral("\\*(\\.\\w+)")).match(filter).captured(1);
    saveLastDirectory(*m_settings, QFileInfo(path).absolutePath());
    m_skinning->exportGltf(path, double(m_timeline->fps()));
}

void MainWindow::showAbout()
{
    const auto caps = m_viewport->capabilities();
    const QString gl = caps ? caps->summary().toHtmlEscaped()
                            : tr("not available — %1").arg(m_viewport->errorMessage().toHtmlEscaped());
    QMessageBox::about(this, tr("About TrimLab"),
                       tr("<h3>TrimLab %1</h3>"
                          "<p>Self-trimmed rendering of self-crossing surfaces by their winding number, on the GPU "
                          "with a choice of multi-fragment methods, checked against an exact CPU ray caster.</p>"
                          "<p><b>OpenGL:</b> %2<br><b>Qt:</b> %3</p>")
                           .arg(QStringLiteral(TRIMLAB_VERSION), gl, QString::fromLatin1(qVersion())));
}

void MainWindow::showMessage(QMessageBox::Icon icon, const QString& title, const QString& text, const QString& details)
{
    // Window-modal and non-blocking: loading and rendering continue behind it.
    auto* box = new QMessageBox(icon, title, text, QMessageBox::Ok, this);
    box->setInformativeText(details);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

void MainWindow::updateTitle()
{
    QString name = m_scene ? QString::fromStdString(m_scene->displayName) : QString();
    const DesignSession* session = m_design->session();
    if (session && !session->projectPath().isEmpty())
        name = QFileInfo(session->projectPath()).fileName();
    // "[*]" is where Qt puts the modified mark (setWindowModified).
    setWindowTitle(name.isEmpty() ? QStringLiteral("TrimLab[*]") : tr("%1[*] — TrimLab").arg(name));
    setWindowModified(m_design->isModified());
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event)
{
    if (!firstLocalFile(event->mimeData()).isEmpty())
        event->acceptProposedAction();
}

// A dropped folder is a mesh animation (a sequence of pose files); a dropped file a mesh.
void MainWindow::dropEvent(QDropEvent* event)
{
    const QString path = firstLocalFile(event->mimeData());
    if (path.isEmpty())
        return;
    event->acceptProposedAction();
    if (QFileInfo(path).isDir())
        openAnimation(path);
    else
        openSource(path);
}

} // namespace trimlab::ui
