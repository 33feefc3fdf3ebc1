#include "ui/render_panel/render_workspace.h"

#include "ui/common/current_document.h"
#include "ui/common/window_context.h"
#include "ui/render_panel/frame_stats_labels.h"
#include "ui/render_panel/frame_stats_panel.h"
#include "ui/render_panel/inspect_group.h"
#include "ui/render_panel/method_group.h"
#include "ui/render_panel/method_timing_panel.h"
#include "ui/render_panel/render_panel.h"
#include "ui/render_panel/render_settings_store.h"
#include "ui/viewport/viewport_widget.h"

#include "render/trim_renderer.h"

#include <QDockWidget>
#include <QMainWindow>
#include <QStatusBar>
#include <QVBoxLayout>

#include <optional>
#include <string>

namespace trimlab::ui {

RenderWorkspace::RenderWorkspace(const WindowContext& context, ViewportWidget* viewport, QObject* parent)
    : QObject(parent), m_context(context), m_viewport(viewport)
{
    m_statsLabels = new FrameStatsLabels(m_context.window().statusBar());
    createRenderDock();
    createStatsDock();
    connectViewport();
    connect(m_panel, &RenderPanel::renderChoicesChanged, this, &RenderWorkspace::choicesChanged);
    connect(m_panel, &RenderPanel::viewDirectionRequested, this, [this] {
        const Camera camera = m_viewport->camera();
        m_panel->setClipNormal(camera.target - camera.eye);
    });
    connect(m_statsPanel, &FrameStatsPanel::methodRequested, this, &RenderWorkspace::chooseMethod);
    connect(m_statsPanel, &FrameStatsPanel::kRequested, this, &RenderWorkspace::chooseK);
    const auto showDocument = [this] {
        if (const Document* document = m_context.document().get())
            showDocumentSettings(document->settings());
    };
    connect(&m_context.document(), &CurrentDocument::replaced, this, showDocument);
    connect(&m_context.document(), &CurrentDocument::settingsChanged, this, showDocument);
}

void RenderWorkspace::createRenderDock()
{
    m_panel = new RenderPanel;
    m_dock = m_context.addSideDock(tr("Render"), QStringLiteral("renderDock"), m_panel);
}

void RenderWorkspace::createStatsDock()
{
    auto* content = new QWidget;
    auto* layout = new QVBoxLayout(content);
    m_statsPanel = new FrameStatsPanel(content);
    m_timingPanel = new MethodTimingPanel(m_viewport, content);
    layout->addWidget(m_statsPanel);
    layout->addWidget(m_timingPanel);
    layout->addStretch();
    // A tab beside the Render panel rather than a split below it: the panel keeps the
    // window's height (the status bar shows the frame's main numbers meanwhile).
    m_statsDock = m_context.addSideDock(tr("Frame statistics"), QStringLiteral("frameStatsDock"), content, m_dock);
}

void RenderWorkspace::connectViewport()
{
    connect(m_viewport, &ViewportWidget::frameRendered, m_statsLabels, &FrameStatsLabels::showStats);
    connect(m_viewport, &ViewportWidget::frameRendered, this, &RenderWorkspace::showFrameStatistics);
    connect(m_viewport, &ViewportWidget::framePixelSizeChanged, this, &RenderWorkspace::refreshMemoryEstimate);
    // Queued: the viewport reports from inside paintGL, where no dialog may open.
    connect(m_viewport, &ViewportWidget::renderError, this, &RenderWorkspace::reportRenderError, Qt::QueuedConnection);
    // Not an error dialog: the view still shows a correct image, rendered another way.
    const auto showNotice = [this](const QString& message) { m_context.showStatus(message, 4 * kStatusMessageMs); };
    connect(m_viewport, &ViewportWidget::memoryFallback, this, showNotice, Qt::QueuedConnection);
    // Nor is a GPU reset: the view re-creates its context and shows the same frame.
    connect(m_viewport, &ViewportWidget::contextLost, this, showNotice, Qt::QueuedConnection);
}

RenderChoices RenderWorkspace::choices() const
{
    return m_panel->renderChoices();
}

void RenderWorkspace::setChoices(const RenderChoices& choices)
{
    m_panel->setRenderChoices(choices);
}

void RenderWorkspace::restoreSettings()
{
    m_panel->setRenderChoices(loadRenderChoices(m_context.settings()));
}

timeline::DocumentSettings RenderWorkspace::documentSettings() const
{
    const RenderChoices choices = m_panel->renderChoices();
    timeline::DocumentSettings settings;
    settings.trim = choices.trim;
    settings.trim.csg = CsgSettings{}; // the scene's (Scene panel)
    settings.classification =
        choices.dynamicRules ? timeline::Classification::Dynamic : timeline::Classification::Static;
    settings.capSpacingFraction = choices.capSpacingFraction;
    return settings;
}

void RenderWorkspace::showDocumentSettings(const timeline::DocumentSettings& settings)
{
    if (settings == documentSettings())
        return;
    RenderChoices choices = m_panel->renderChoices();
    choices.trim = settings.trim;
    choices.trim.csg = CsgSettings{};
    choices.dynamicRules = settings.classification == timeline::Classification::Dynamic;
    choices.capSpacingFraction = settings.capSpacingFraction;
    m_panel->setRenderChoices(choices);
}

namespace {

/// What the dynamic rules cannot render beside the trim (render/trim_renderer.cpp's
/// checkInspection): the static rule's inspection features, off.
void dropStaticOnlyFeatures(TrimSettings& settings)
{
    settings.cap.enabled = false;
    settings.highlight = HighlightSettings{};
    settings.transparency.enabled = false;
    settings.csg = CsgSettings{};
}

} // namespace

TrimSettings RenderWorkspace::apply(const CsgSettings& csg, bool historyShown)
{
    RenderChoices choices = m_panel->renderChoices();
    TrimSettings effective = choices.trim;
    effective.csg = csg; // the scene's: it belongs to the scene, not to the saved choices
    // The winding index is undefined for open or inconsistently oriented surfaces.
    effective.trimEnabled = effective.trimEnabled && m_panel->sceneTrimmable();
    // Boxes ticked under the static rule stay ticked (and saved) but do not apply while the
    // dynamic rules classify: the view keeps rendering instead of refusing the frame.
    const bool dynamic = historyShown && choices.dynamicRules && effective.trimEnabled;
    m_panel->inspectGroup()->setUnavailableReason(
        dynamic ? tr("Capping, highlighting, X-ray and CSG need the static rule: set Classification to “Static "
                     "rule” to use them.")
                : QString());
    if (dynamic)
        dropStaticOnlyFeatures(effective);
    MethodGroup* methods = m_panel->methodGroup();
    methods->setUnavailableMethods([&](const render::MethodInfo& info) -> std::optional<QString> {
        const std::optional<std::string> refusal = render::methodRefusal(info, dynamic, effective);
        return refusal ? std::optional<QString>(QString::fromStdString(*refusal)) : std::nullopt;
    });
    moveOffUnavailableMethod(choices);
    saveRenderChoices(m_context.settings(), choices);
    m_viewport->setTrimSettings(effective);
    m_viewport->setMethod(choices.method);
    m_viewport->setMethodParameters(choices.methodParameters());
    refreshMemoryEstimate();
    return effective;
}

// A method that cannot render what is asked is disabled in the list; when it is the one
// chosen, the first that can takes over and the status bar says why (instead of a frame
// refused with a dialog).
void RenderWorkspace::moveOffUnavailableMethod(RenderChoices& choices)
{
    MethodGroup* methods = m_panel->methodGroup();
    const QString reason = methods->unavailableReason(choices.method);
    const std::optional<render::FragmentMethodKind> fallback = methods->firstAvailableMethod();
    if (reason.isEmpty() || !fallback)
        return;
    choices.method = *fallback;
    methods->setChoices(choices.method, choices.k, choices.sharedCounters);
    m_context.showStatus(tr("Switched to %1. %2").arg(methodDisplayName(render::methodInfo(*fallback)), reason),
                         4 * kStatusMessageMs);
}

void RenderWorkspace::showSceneInfo(const Bounds& bounds, bool trimmable, const QString& reason)
{
    m_panel->setSceneInfo(bounds, trimmable, reason);
}

void RenderWorkspace::setClipBounds(const Bounds& bounds)
{
    m_panel->setClipBounds(bounds);
}

void RenderWorkspace::reportRenderError(const QString& message)
{
    m_statsLabels->clear();
    m_statsPanel->clear();
    m_context.showMessage(QMessageBox::Critical, tr("OpenGL problem"), tr("The viewport cannot render."), message);
}

void RenderWorkspace::refreshMemoryEstimate()
{
    m_panel->setMemoryEstimate(m_viewport->memoryEstimate());
}

void RenderWorkspace::showFrameStatistics()
{
    if (const auto& frame = m_viewport->lastFrame()) {
        m_statsPanel->showFrame(*frame);
        m_statsLabels->showHighlights(frame->settings.highlight, frame->stats.counts);
    }
    refreshMemoryEstimate();
}

void RenderWorkspace::chooseMethod(render::FragmentMethodKind method)
{
    RenderChoices choices = m_panel->renderChoices();
    choices.method = method;
    m_panel->setRenderChoices(choices);
    emit choicesChanged();
    m_context.showStatus(tr("Switched to %1.").arg(methodDisplayName(render::methodInfo(method))));
}

void RenderWorkspace::chooseK(int k)
{
    RenderChoices choices = m_panel->renderChoices();
    choices.k = k;
    m_panel->setRenderChoices(choices);
    emit choicesChanged();
    m_context.showStatus(tr("k raised to %1.").arg(k));
}

} // namespace trimlab::ui
