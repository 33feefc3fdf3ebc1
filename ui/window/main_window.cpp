#include "ui/window/main_window.h"

#include "render/image_file.h"

#include "ui/animation/animation_workspace.h"
#include "ui/animation/timeline_panel.h"
#include "ui/common/loaded_animation.h"
#include "ui/animation/open_animation_dialog.h"
#include "ui/common/current_document.h"
#include "ui/common/window_context.h"
#include "ui/design/design_session.h"
#include "ui/design/design_workspace.h"
#include "ui/design/project_files.h"
#include "ui/design/session_recovery.h"
#include "ui/inspect/inspect_workspace.h"
#include "ui/inspect/scene_panel.h"
#include "ui/inspect/solid_measures_view.h"
#include "ui/render_panel/render_workspace.h"
#include "ui/skeleton/skeleton_workspace.h"
#include "ui/skinning/skinning_workspace.h"
#include "ui/surface/surface_workspace.h"
#include "ui/viewport/orientation_axes.h"
#include "ui/viewport/viewport_widget.h"
#include "ui/common/mesh_file_filter.h"
#include "ui/window/dock_tab_bars.h"
#include "ui/window/help_dialogs.h"
#include "ui/window/messages_panel.h"
#include "ui/window/scene_statistics.h"
#include "ui/window/scene_switch.h"

#include "core/catalog/scene_source.h"

#include <QAction>
#include <QCloseEvent>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QIcon>
#include <QLabel>
#include <QMenuBar>
#include <QMimeData>
#include <QSettings>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>

#include <glm/vec3.hpp>

#include <initializer_list>

namespace trimlab::ui {

namespace {

const QString kGeometryKey = QStringLiteral("window/geometry");
const QString kStateKey = QStringLiteral("window/state");

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

/// The dock's show/hide action, titled for the View menu.
void addDockToggle(QMenu* menu, QDockWidget* dock, const QString& text)
{
    QAction* toggle = dock->toggleViewAction();
    toggle->setText(text);
    menu->addAction(toggle);
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
    setWindowIcon(QIcon(QStringLiteral(":/icons/trimlab.svg")));
    setAcceptDrops(true);
    // Tabs beside the side docks, not below them: six panels' titles do not fit across a
    // 400-pixel dock ("Re…", "Segmenta…"), and a column of tabs has room for more.
    setDockOptions(dockOptions() | QMainWindow::VerticalTabs);
    keepDockTabTitlesWhole(*this);
    createCentralView();
    m_document = new CurrentDocument(this);
    m_switch = new SceneSwitch(this, m_viewport, *m_document);
    m_log = new MessageLog(this);
    m_context = std::make_unique<WindowContext>(*this, *m_settings, *m_switch, *m_document, *m_log);
    createWorkspaces();
    createMessagesDock();
    createFileMenu();
    createEditMenu();
    m_surface->addCreateMenu(menuBar());
    createViewMenu();
    createHelpMenu();
    connectWorkspaces();
    restoreSettings();
    updateTitle();
    QTimer::singleShot(0, this, &MainWindow::openDefaultIfNothingRequested);
    QTimer::singleShot(0, m_design->sessionRecovery(), &SessionRecovery::offer);
}

// The workspaces are destroyed with the window's children, after this object's members:
// nothing they report on the way out (a design session's undo stack leaving its clean
// state) may reach the half-destroyed window.
MainWindow::~MainWindow()
{
    for (QObject* part :
         std::initializer_list<QObject*>{m_switch, m_render, m_animation, m_design, m_surface, m_skeleton, m_inspect})
        disconnect(part, nullptr, this, nullptr);
}

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
        m_axes = new OrientationAxes(m_viewport);
        return;
    }
    // No usable OpenGL: a QOpenGLWidget in the window would break the window itself, so
    // the viewport stays detached (loading and the panel still work) and a text explains.
    m_detachedViewport = std::make_unique<ViewportWidget>();
    m_viewport = m_detachedViewport.get();
    m_axes = new OrientationAxes(m_viewport);
    m_viewport->setUnavailable(glProblem);
    auto* label = new QLabel(tr("The 3D view is unavailable.\n\n%1").arg(glProblem), this);
    label->setObjectName(QStringLiteral("viewportUnavailableLabel"));
    label->setAlignment(Qt::AlignCenter);
    label->setWordWrap(true);
    label->setMargin(24);
    setCentralWidget(label);
    QTimer::singleShot(0, this, [this, glProblem] { m_render->reportRenderError(glProblem); });
}

// The order makes the docks' tab order: Render, Segmentation (Skinning), Brush (Surface),
// Skeleton, Scene — with the Render panel in front.
void MainWindow::createWorkspaces()
{
    m_render = new RenderWorkspace(*m_context, m_viewport, this);
    m_animation = new AnimationWorkspace(*m_context, m_viewport, m_render->dock(), this);
    m_design = new DesignWorkspace(*m_context, m_viewport, m_render->dock(), this);
    m_surface = new SurfaceWorkspace(*m_context, *m_design, this);
    m_skeleton = new SkeletonWorkspace(*m_context, m_viewport, m_render->dock(), m_design->brushAction(), this);
    m_inspect = new InspectWorkspace(*m_context, m_viewport, m_render->dock(), this);
    // Adding an object ends a design (several objects are not designed): its unsaved
    // history is asked about; a scene only grows.
    m_inspect->setSaveGuard([this] { return !m_design->session() || m_design->projectFiles()->maybeSave(); });
    m_solidExport = new SolidExport(
        *m_context, [this] { return shownSolid(); }, this);
    auto* measures = new SolidMeasuresView([this] { return shownSolid(); }, m_context->settings());
    m_inspect->panel()->setSolidMeasures(measures);
    connect(m_viewport, &ViewportWidget::frameRendered, measures, &SolidMeasuresView::follow);
    // Raised from behind another tab: measured once the tab shows it.
    connect(m_inspect->dock(), &QDockWidget::visibilityChanged, measures, &SolidMeasuresView::follow,
            Qt::QueuedConnection);
    m_render->dock()->raise();
}

// What File ▸ Export Trimmed Solid writes: the scene of the last frame under its static
// rule or CSG, or why the view shows no solid.
SolidExport::Shown MainWindow::shownSolid() const
{
    SolidExport::Shown shown;
    const auto& frame = m_viewport->lastFrame();
    const std::shared_ptr<const LoadedScene> loaded = scene();
    if (!frame || !frame->scene || !loaded) {
        shown.refusal = tr("Nothing is shown yet.");
        shown.remedy = tr("Open a mesh, a project or a demo first.");
        return shown;
    }
    shown.scene = m_viewport->content()->posedScene(); // the frame shown, not the rest mesh
    shown.settings = frame->settings;
    shown.name = m_context->sceneBaseName(QStringLiteral("trimlab"));
    if (const std::shared_ptr<const LoadedAnimation> playing = animation(); playing && playing->restScene == loaded) {
        shown.animation = playing->animation;
        shown.pose = m_animation->timelinePanel()->pose();
        shown.fps = m_animation->timelinePanel()->fps();
    }
    if (!loaded->trimmable())
        shown.refusal = tr("The scene has no inside: %1").arg(QString::fromStdString(loaded->trimUnavailableReason()));
    else if (!frame->settings.trimEnabled) {
        shown.refusal = tr("Trimming is off, so the view shows no solid.");
        shown.remedy = tr("Turn trimming on in the Render panel and choose the rule that makes the solid.");
    } else if (m_render->choices().dynamicRules && m_design->session()) {
        shown.refusal = tr("Dynamic rules cannot be exported exactly: they remember more than one surface of the "
                           "deformation history.");
        shown.remedy = tr("Choose Static rule under Classification to export what a static rule keeps of the "
                          "frame shown.");
    }
    return shown;
}

void MainWindow::createFileMenu()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* open = file->addAction(tr("&Open…"), this, &MainWindow::showOpenDialog);
    open->setShortcut(QKeySequence::Open);
    QMenu* demos = file->addMenu(tr("Open &Demo"));
    demos->setObjectName(QStringLiteral("openDemoMenu"));
    for (const DemoEntry& demo : builtInDemos()) {
        const QString source = QString::fromStdString(demo.source);
        QAction* action =
            demos->addAction(source.mid(int(kDemoPrefix.size())), this, [this, source] { openSource(source); });
        action->setStatusTip(QString::fromUtf8(demo.description.data(), qsizetype(demo.description.size())));
        action->setToolTip(action->statusTip());
    }
    QMenu* recent = file->addMenu(tr("Open &Recent"));
    QAction* addObject = file->addAction(tr("Add O&bject…"), m_inspect, &InspectWorkspace::showAddObjectDialog);
    addObject->setObjectName(QStringLiteral("addObjectAction"));
    addObject->setStatusTip(tr("Load a mesh file into the scene shown as one more object (CSG, collisions)"));
    file->addSeparator();
    QAction* openAnimation = file->addAction(tr("Open &Animation…"), this, &MainWindow::showOpenAnimationDialog);
    openAnimation->setShortcut(QKeySequence(tr("Ctrl+Shift+O")));
    QMenu* recentAnimations = file->addMenu(tr("Open Recent A&nimation"));
    file->addSeparator();
    QAction* exportImage = file->addAction(tr("&Export Image…"), this, &MainWindow::showExportDialog);
    exportImage->setShortcut(QKeySequence(tr("Ctrl+E")));
    QAction* exportSolid = file->addAction(tr("Export &Trimmed Solid…"), m_solidExport, &SolidExport::showExportDialog);
    exportSolid->setObjectName(QStringLiteral("exportTrimmedSolidAction"));
    exportSolid->setStatusTip(tr("Write the solid the view shows (its rule or CSG, exact) as a closed mesh: OBJ, "
                                 "PLY, STL or glTF"));
    file->addSeparator();
    m_design->addFileActions(file);
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);
    quit->setMenuRole(QAction::QuitRole);
    m_switch->attach(*m_context, {m_render, m_animation, m_design, m_skeleton, m_inspect}, recent, recentAnimations);
}

void MainWindow::createEditMenu()
{
    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    edit->addAction(m_design->undoAction());
    edit->addAction(m_design->redoAction());
    edit->addSeparator();
    edit->addAction(m_design->brushAction());
    edit->addAction(m_design->newSetAction());
    edit->addAction(m_surface->controlPointsAction());
    edit->addSeparator();
    // Open meshes and animations (captured scans, horse-gallop) have holes the trim rules
    // cannot classify; closing them by fans is the remedy their refusal names.
    QAction* closeHoles = edit->addAction(tr("Close &Holes"), m_switch, &SceneSwitch::closeShownHoles);
    closeHoles->setObjectName(QStringLiteral("closeHolesAction"));
    closeHoles->setStatusTip(tr("Close each hole of the open mesh or animation by a fan to its centroid, so that "
                                "the trim rules apply"));
    closeHoles->setEnabled(false);
    connect(m_switch, &SceneSwitch::sceneShown, closeHoles,
            [this, closeHoles] { closeHoles->setEnabled(m_switch->shownHasHoles()); });
    QToolBar* tools = addToolBar(tr("Design"));
    tools->setObjectName(QStringLiteral("designToolBar"));
    tools->addAction(m_design->brushAction());
    tools->addAction(m_design->newSetAction());
    tools->addAction(m_surface->controlPointsAction());
    tools->addAction(m_design->undoAction());
    tools->addAction(m_design->redoAction());
}

void MainWindow::createViewMenu()
{
    QMenu* view = menuBar()->addMenu(tr("&View"));
    // Single-key shortcuts act only while the viewport has focus (never while typing).
    QAction* fit = view->addAction(tr("&Fit to View"), m_viewport, &ViewportWidget::fitToView);
    fit->setShortcut(QKeySequence(Qt::Key_F));
    fit->setShortcutContext(Qt::WidgetShortcut);
    m_viewport->addAction(fit);
    QAction* reset = view->addAction(tr("&Reset View"), m_viewport, &ViewportWidget::resetView);
    reset->setShortcut(QKeySequence(Qt::Key_Home));
    reset->setShortcutContext(Qt::WidgetShortcut);
    m_viewport->addAction(reset);
    addViewPresets(view);
    QAction* statistics = view->addAction(tr("&Mesh Statistics…"), this, &MainWindow::showSceneStatistics);
    statistics->setObjectName(QStringLiteral("meshStatisticsAction"));
    statistics->setShortcut(QKeySequence(tr("Ctrl+I")));
    QAction* axes = view->addAction(tr("Orientation &Axes"));
    axes->setObjectName(QStringLiteral("showAxesAction"));
    axes->setCheckable(true);
    axes->setChecked(m_settings->value(QStringLiteral("view/showAxes"), true).toBool());
    m_axes->setVisible(axes->isChecked());
    connect(axes, &QAction::toggled, this, [this](bool on) {
        m_axes->setVisible(on);
        m_settings->setValue(QStringLiteral("view/showAxes"), on);
    });
    view->addSeparator();
    addDockToggle(view, m_render->dock(), tr("Render &Panel"));
    addDockToggle(view, m_inspect->dock(), tr("S&cene Panel"));
    addDockToggle(view, m_render->statsDock(), tr("Frame &Statistics"));
    addDockToggle(view, m_animation->segmentationDock(), tr("Se&gmentation Panel"));
    addDockToggle(view, m_animation->skinning()->dock(), tr("S&kinning Panel"));
    addDockToggle(view, m_skeleton->dock(), tr("Ske&leton Panel"));
    addDockToggle(view, m_animation->timelineDock(), tr("&Timeline"));
    addDockToggle(view, m_design->brushDock(), tr("&Brush Panel"));
    addDockToggle(view, m_surface->dock(), tr("S&urface Panel"));
    addDockToggle(view, m_design->timelineDock(), tr("&Deformation Timeline"));
    addDockToggle(view, m_messagesDock, tr("M&essages"));
    m_messagesDock->toggleViewAction()->setObjectName(QStringLiteral("showMessagesAction"));
}

void MainWindow::createMessagesDock()
{
    m_messagesDock =
        m_context->addBottomDock(tr("Messages"), QStringLiteral("messagesDock"), new MessagesPanel(*m_log));
    m_messagesDock->hide(); // until asked for (restoreSettings brings back a dock left open)
    statusBar()->installEventFilter(this);
    statusBar()->setToolTip(tr("Click for every message so far (View ▸ Messages)"));
}

bool MainWindow::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == statusBar() && event->type() == QEvent::MouseButtonRelease) {
        m_messagesDock->show();
        m_messagesDock->raise();
    }
    return QMainWindow::eventFilter(watched, event);
}

// Front, back, left, right, top and bottom on 1, 3 and 7 as on Blender's numeric keypad
// (Ctrl: the opposite side; keypad and top-row digits alike) while the view has the focus.
void MainWindow::addViewPresets(QMenu* view)
{
    QMenu* presets = view->addMenu(tr("View &From"));
    presets->setObjectName(QStringLiteral("viewPresetsMenu"));
    struct Preset {
        const char* text;
        const char* name;
        glm::dvec3 direction; // eye → target
        QKeySequence keys;
    };
    const Preset list[] = {
        {QT_TR_NOOP("&Front"), "viewFrontAction", {0.0, 0.0, -1.0}, QKeySequence(Qt::Key_1)},
        {QT_TR_NOOP("&Back"), "viewBackAction", {0.0, 0.0, 1.0}, QKeySequence(Qt::ControlModifier | Qt::Key_1)},
        {QT_TR_NOOP("&Right"), "viewRightAction", {-1.0, 0.0, 0.0}, QKeySequence(Qt::Key_3)},
        {QT_TR_NOOP("&Left"), "viewLeftAction", {1.0, 0.0, 0.0}, QKeySequence(Qt::ControlModifier | Qt::Key_3)},
        {QT_TR_NOOP("&Top"), "viewTopAction", {0.0, -1.0, 0.0}, QKeySequence(Qt::Key_7)},
        {QT_TR_NOOP("B&ottom"), "viewBottomAction", {0.0, 1.0, 0.0}, QKeySequence(Qt::ControlModifier | Qt::Key_7)},
    };
    for (const Preset& preset : list) {
        const glm::dvec3 direction = preset.direction;
        QAction* action =
            presets->addAction(tr(preset.text), m_viewport, [this, direction] { m_viewport->viewAlong(direction); });
        action->setObjectName(QLatin1String(preset.name));
        action->setShortcut(preset.keys);
        action->setShortcutContext(Qt::WidgetShortcut);
        m_viewport->addAction(action);
    }
}

void MainWindow::createHelpMenu()
{
    QMenu* help = menuBar()->addMenu(tr("&Help"));
    QAction* guide = help->addAction(tr("&User Guide"), this, [this] { showUserGuide(this); });
    guide->setObjectName(QStringLiteral("userGuideAction"));
    guide->setShortcut(QKeySequence::HelpContents);
    QAction* keys = help->addAction(tr("&Keyboard Shortcuts"), this, [this] { showKeyboardShortcuts(*this); });
    keys->setObjectName(QStringLiteral("keyboardShortcutsAction"));
    help->addSeparator();
    QAction* about = help->addAction(tr("&About TrimLab"), this, &MainWindow::showAbout);
    about->setMenuRole(QAction::AboutRole);
}

void MainWindow::connectWorkspaces()
{
    connect(m_switch, &SceneSwitch::sceneShown, this, &MainWindow::applyRenderChoices);
    connect(m_switch, &SceneSwitch::boundsChanged, this, &MainWindow::applyRenderChoices);
    // The title follows the document shown: its name or project file, and its '*'.
    connect(m_document, &CurrentDocument::titleChanged, this, &MainWindow::updateTitle);
    connect(m_document, &CurrentDocument::modifiedChanged, this, &MainWindow::updateTitle);
    connect(m_switch, &SceneSwitch::sceneLoaded, this, &MainWindow::sceneLoaded);
    connect(m_switch, &SceneSwitch::animationLoaded, this, &MainWindow::animationLoaded);
    connect(m_switch, &SceneSwitch::sceneLoadFailed, this, &MainWindow::sceneLoadFailed);
    connect(m_switch, &SceneSwitch::objectAdded, this, &MainWindow::objectAdded);
    connect(m_render, &RenderWorkspace::choicesChanged, this, &MainWindow::applyRenderChoices);
    connect(m_inspect, &InspectWorkspace::csgChanged, this, &MainWindow::applyRenderChoices);
    connect(m_design, &DesignWorkspace::sessionChanged, this, [this] {
        m_inspect->setDesignSession(m_design->session());
        applyRenderChoices(); // whether the dynamic rules are shown depends on the session
    });
}

void MainWindow::restoreSettings()
{
    m_animation->restoreSettings();
    m_skeleton->restoreSettings();
    m_render->restoreSettings();
    applyRenderChoices();
    m_design->restoreSettings();
    if (!restoreGeometry(m_settings->value(kGeometryKey).toByteArray()))
        resize(1100, 720);
    if (!restoreState(m_settings->value(kStateKey).toByteArray())) {
        resizeDocks({m_render->dock()}, {400}, Qt::Horizontal);
    }
    m_animation->hideAnimationDocks(); // until an animation is opened
    m_design->timelineDock()->hide();  // until a deformation history starts
}

void MainWindow::saveWindowState()
{
    m_settings->setValue(kGeometryKey, saveGeometry());
    m_settings->setValue(kStateKey, saveState());
    m_settings->sync();
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (!m_switch->confirmReplacingShown()) {
        event->ignore();
        return;
    }
    saveWindowState();
    QMainWindow::closeEvent(event);
}

void MainWindow::openSource(const QString& source)
{
    m_switch->openSource(source);
}

void MainWindow::openAnimation(const QString& source)
{
    m_switch->openAnimation(source);
}

void MainWindow::openDefaultIfNothingRequested()
{
    if (!m_switch->openRequested())
        openSource(defaultSource());
}

bool MainWindow::isLoading() const
{
    return m_switch->isLoading();
}

std::shared_ptr<const LoadedScene> MainWindow::scene() const
{
    return m_switch->shownScene();
}

SceneLoader* MainWindow::sceneLoader() const
{
    return m_switch->sceneLoader();
}

AnimationOpener* MainWindow::animationOpener() const
{
    return m_switch->animationOpener();
}

QStringList MainWindow::recentFiles() const
{
    return m_switch->recentFiles();
}

QStringList MainWindow::recentAnimations() const
{
    return m_switch->recentAnimations();
}

Document* MainWindow::document() const
{
    return m_document->get();
}

std::shared_ptr<const LoadedAnimation> MainWindow::animation() const
{
    return m_animation->animation();
}

void MainWindow::showOpenAnimationDialog()
{
    const QString source = OpenAnimationDialog::getSource(this, m_context->lastDirectory());
    if (source.isEmpty())
        return;
    const QFileInfo info(source);
    m_context->rememberDirectory(info.isDir() ? info.absoluteFilePath() : info.absolutePath());
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
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open Mesh or Project"), m_context->lastDirectory(), filter);
    if (path.isEmpty())
        return;
    m_context->rememberDirectory(QFileInfo(path).absolutePath());
    openSource(path);
}

// Where the features' choices meet: the Render panel's choices with the scene's CSG
// expression (inspect) and the design session's classification (design).
void MainWindow::applyRenderChoices()
{
    if (Document* document = m_document->get())
        document->setSettings(m_render->documentSettings());
    const TrimSettings effective = m_render->apply(m_inspect->csg(), m_design->session() != nullptr);
    const RenderChoices choices = m_render->choices();
    m_design->setRenderMode(choices.dynamicRules, choices.trim.rule, effective.trimEnabled);
    m_animation->setBaseRule(choices.trim.rule);
}

bool MainWindow::exportImage(const QString& path, QString* error)
{
    const QImage image = m_viewport->readColorImage();
    QString reason;
    if (image.isNull())
        reason = tr("Nothing has been rendered yet.");
    else {
        try {
            render::writeImageFile(image.convertToFormat(QImage::Format_RGB32), path, "png");
        } catch (const std::exception& e) {
            reason = QString::fromUtf8(e.what());
        }
    }
    if (error)
        *error = reason;
    return reason.isEmpty();
}

void MainWindow::showExportDialog()
{
    const QString path =
        m_context->askSavePath(tr("Export Image"), {tr("PNG image (*.png)")},
                               m_context->sceneBaseName(QStringLiteral("trimlab")) + QStringLiteral(".png"));
    if (path.isEmpty())
        return;
    QString error;
    if (exportImage(path, &error))
        m_context->showStatus(tr("Saved %1").arg(path));
    else
        m_context->showMessage(QMessageBox::Warning, tr("Export Image"), tr("The image was not saved."), error);
}

void MainWindow::showSceneStatistics()
{
    if (!m_statistics) {
        m_statistics = new SceneStatisticsDialog(
            m_viewport->content(), [this] { return shownSolid(); }, this);
        // Follows what is shown while it stays open.
        connect(m_switch, &SceneSwitch::sceneShown, m_statistics, [this] { m_statistics->showScene(scene()); });
    }
    m_statistics->showScene(scene());
    m_statistics->show();
    m_statistics->raise();
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

void MainWindow::updateTitle()
{
    const Document* document = m_document->get();
    const QString name = document ? document->title() : QString();
    // "[*]" is where Qt puts the modified mark (setWindowModified).
    setWindowTitle(name.isEmpty() ? QStringLiteral("TrimLab[*]") : tr("%1[*] — TrimLab").arg(name));
    setWindowModified(document && document->isModified());
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
