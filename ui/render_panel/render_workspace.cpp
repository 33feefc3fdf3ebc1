#include "ui/render_panel/render_workspace.h"

#include "ui/common/window_context.h"
#include "ui/render_panel/frame_stats_labels.h"
#include "ui/render_panel/frame_stats_panel.h"
#include "ui/render_panel/method_group.h"
#include "ui/render_panel/method_timing_panel.h"
#include "ui/render_panel/render_panel.h"
#include "ui/render_panel/render_settings_store.h"
#include "ui/viewport/viewport_widget.h"

#include <QDockWidget>
#include <QMainWindow>
#include <QStatusBar>
#include <QVBoxLayout>

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
    m_statsDock = m_context.addSideDock(tr("Frame statistics"), QStringLiteral("frameStatsDock"), content);
    m_context.window().splitDockWidget(m_dock, m_statsDock, Qt::Vertical);
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

TrimSettings RenderWorkspace::apply(const CsgSettings& csg)
{
    const RenderChoices choices = m_panel->renderChoices();
    saveRenderChoices(m_context.settings(), choices);
    TrimSettings effective = choices.trim;
    effective.csg = csg; // the scene's: it belongs to the scene, not to the saved choices
    // The winding index is undefined for open or inconsistently oriented surfaces.
    effective.trimEnabled = effective.trimEnabled && m_panel->sceneTrimmable();
    m_viewport->setTrimSettings(effective);
    m_viewport->setMethod(choices.method);
    m_viewport->setMethodParameters(choices.methodParameters());
    refreshMemoryEstimate();
    return effective;
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
