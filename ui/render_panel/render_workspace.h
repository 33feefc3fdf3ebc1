#pragma once
/// \file
/// The render feature of the main window: the Render dock (rule, method, parameters,
/// clipping, caps, highlights, X-ray: RenderPanel), the Frame statistics dock (the last
/// frame's numbers with overflow advice, and the per-method timing chart), the frame
/// numbers in the status bar, and what the viewport reports about its frames — a render
/// error as a dialog, a memory fallback or a GPU reset as a status message. The chosen
/// render choices persist in the settings.
///
/// The window composes the choices with what other features own (the scene's CSG, the
/// design session's rules) in MainWindow::applyRenderChoices; this object applies the
/// result to the viewport (apply()). The panel edits the view settings of the document
/// shown (ui/common/document.h): when another document is shown, or its settings change
/// (objects added), the panel shows them; the method, k, S and the memory budget are the
/// user's preferences.

#include "ui/render_panel/render_choices.h"

#include "core/timeline/view_settings.h"
#include "core/trim/inspect_settings.h"
#include "render/mfr/fragment_method.h"

#include <QObject>

class QDockWidget;

namespace trimlab::ui {

class FrameStatsLabels;
class FrameStatsPanel;
class MethodTimingPanel;
class RenderPanel;
class ViewportWidget;
class WindowContext;

class RenderWorkspace : public QObject {
    Q_OBJECT
public:
    RenderWorkspace(const WindowContext& context, ViewportWidget* viewport, QObject* parent = nullptr);

    [[nodiscard]] RenderPanel* panel() const { return m_panel; }
    [[nodiscard]] FrameStatsPanel* statsPanel() const { return m_statsPanel; }
    [[nodiscard]] MethodTimingPanel* timingPanel() const { return m_timingPanel; }
    [[nodiscard]] QDockWidget* dock() const { return m_dock; }
    [[nodiscard]] QDockWidget* statsDock() const { return m_statsDock; }

    /// The choices shown in the panel, and replacing them (no choicesChanged()).
    [[nodiscard]] RenderChoices choices() const;
    void setChoices(const RenderChoices& choices);
    /// The saved choices into the panel (firstStartRenderChoices() without saved ones).
    void restoreSettings();
    /// The part of the panel's choices that belongs to the document shown (trim, rule,
    /// classification, clipping, caps, highlights, X-ray), in world space.
    [[nodiscard]] timeline::DocumentSettings documentSettings() const;
    /// Shows a document's settings in the panel (no choicesChanged()); the method and its
    /// parameters stay the user's.
    void showDocumentSettings(const timeline::DocumentSettings& settings);
    /// Saves the panel's choices and renders with them: `csg` is the scene's expression;
    /// trimming is off for scenes that cannot be trimmed. `historyShown`: a deformation
    /// history is shown, so the dynamic rules classify when chosen — capping,
    /// highlighting, X-ray and CSG are then disabled in the panel (kept ticked) and left
    /// out. Methods that cannot render the result are disabled with the reason; a chosen
    /// one is replaced by the first that can (status message). Returns the trim settings
    /// the viewport now renders with.
    TrimSettings apply(const CsgSettings& csg, bool historyShown);

    /// The shown scene's bounds (clip offsets, cap spacing) and whether it can be trimmed
    /// (`reason` says why not).
    void showSceneInfo(const Bounds& bounds, bool trimmable, const QString& reason);
    /// New bounds of the scene shown (an object moved): clip offsets, cap spacing.
    void setClipBounds(const Bounds& bounds);
    /// The viewport cannot render: a dialog, and no frame numbers.
    void reportRenderError(const QString& message);

signals:
    /// The user edited the render choices.
    void choicesChanged();

private:
    void createRenderDock();
    void createStatsDock();
    void connectViewport();
    void refreshMemoryEstimate();
    void showFrameStatistics();
    void chooseMethod(render::FragmentMethodKind method);
    void chooseK(int k);
    void moveOffUnavailableMethod(RenderChoices& choices);

    const WindowContext& m_context;
    ViewportWidget* m_viewport;
    RenderPanel* m_panel = nullptr;
    QDockWidget* m_dock = nullptr;
    FrameStatsPanel* m_statsPanel = nullptr;
    MethodTimingPanel* m_timingPanel = nullptr;
    QDockWidget* m_statsDock = nullptr;
    FrameStatsLabels* m_statsLabels = nullptr;
};

} // namespace trimlab::ui
