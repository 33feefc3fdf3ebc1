#pragma once
/// \file
/// Picking and dragging the control points of an editable surface (thesis 8.2), a
/// ViewportTool like the brush. With the tool on and a surface session:
/// - a left click within kPickPixels of a projected control point (the overlay's)
///   selects it alone; Shift + click adds or removes it; a click on empty space clears
///   the selection (and the press goes on to the camera: dragging there orbits);
/// - a left drag that starts on a point moves the selection (the grabbed point joins it
///   if it was not selected): in the view plane through the grabbed point's depth, so it
///   follows the cursor; with Ctrl along the selection's average surface normal
///   (EditableSurface::controlPointNormal), cursor up pulls out. Tied NURBS points (seam
///   twins, poles) move with them;
/// - while dragging, the surface is re-evaluated and shown live (the viewport's pose, or
///   its dynamic shown level under the dynamic rules, as the brush's drag does), the net
///   follows; a subdivision surface's pose is evaluated by the viewport on the GPU from the
///   control points where it can (render/frame/gpu_subdivision.h), the CPU's evaluation
///   staying what the still, the exports and the recorded frame use; the release records ONE undoable frame (AppendFrameCommand with
///   controlEditFrame), a click without movement records nothing;
/// - Ctrl + left drag from empty space draws a box; the points inside it join the
///   selection on release (box selection);
/// - Alt + left, right and middle drag move the camera; hovering rings the point under
///   the cursor.
/// On an earlier frame than the last the press is refused with a status message.

#include "core/design/brush_drag.h"
#include "ui/viewport/viewport_tool.h"

#include "render/content_publisher.h"
#include "render/frame/subdivision_stencils.h"

#include "core/surface/surface_definition.h"
#include "core/timeline/control_edit.h"
#include "core/trim/dynamic_rule.h"

#include <QObject>
#include <QPointF>
#include <QPointer>
#include <QRectF>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace trimlab {
class ControlPreview;
}

namespace trimlab::ui {

class ControlNetOverlay;
class DesignSession;
class ViewportWidget;

class ControlPointTool : public QObject, public ViewportTool {
    Q_OBJECT
public:
    /// How far (logical pixels) from a projected point a click still picks it.
    static constexpr double kPickPixels = 8.0;

    ControlPointTool(ViewportWidget* viewport, ControlNetOverlay* overlay, QObject* parent = nullptr);
    ~ControlPointTool() override;

    /// The history to edit (nullptr, or one without a surface: the tool declines every
    /// press). Clears the selection. While on, the tool leaves the viewport without a
    /// history and takes it back, unless another tool has it, when a history comes.
    void setSession(DesignSession* session);
    /// Installed on the viewport while on and a history is edited.
    void setEnabled(bool enabled);
    [[nodiscard]] bool isEnabled() const { return m_enabled; }
    /// Whether the viewport renders the dynamic rules (drags then replace its shown level).
    void setDynamicRules(bool dynamic) { m_dynamic = dynamic; }
    /// Shows the session's shown frame again (the workspace's refresh), called when a
    /// previewed drag ends without a new frame.
    void setViewRestorer(std::function<void()> restore) { m_restoreView = std::move(restore); }
    /// Decides whether a finished edit may be recorded (the homogeneous confluent rule);
    /// returns the reason to refuse, or nullopt.
    using Guard = std::function<std::optional<QString>(const timeline::Frame& frame)>;
    void setGuard(Guard guard) { m_guard = std::move(guard); }

    /// Selected control points, ascending and unique.
    [[nodiscard]] const std::vector<std::uint32_t>& selection() const { return m_selection; }
    void setSelection(std::vector<std::uint32_t> selection);
    [[nodiscard]] bool isDragging() const { return m_dragging; }
    /// Milliseconds the last drag update took (evaluation plus handing the positions on).
    [[nodiscard]] double lastUpdateMilliseconds() const { return m_lastUpdateMs; }

    bool pressed(QMouseEvent& event) override;
    void moved(QMouseEvent& event) override;
    void released(QMouseEvent& event) override;
    void hovered(QPointF position) override;
    void left() override;
    [[nodiscard]] QString mouseHelp() const override;

signals:
    void statusMessage(const QString& message);
    void selectionChanged(int count);

private:
    [[nodiscard]] bool startDrag(std::uint32_t grabbed, QPointF position, bool alongNormal);
    [[nodiscard]] std::vector<ControlPointTarget> targetsFor(QPointF position) const;
    void preview(const std::vector<ControlPointTarget>& targets);
    void showPreviewPositions(const std::vector<glm::vec3>& positions);
    void updateGpuStencils();
    void commit(const std::vector<ControlPointTarget>& targets);
    void cancelDrag();
    void selectInBox(const QRectF& box);
    void endPreview();

    ViewportWidget* m_viewport;
    ControlNetOverlay* m_overlay;
    render::ContentPublisher m_shown; ///< previews: the design history's pose and shown level
    QPointer<DesignSession> m_session;
    bool m_enabled = false;
    bool m_dynamic = false;
    std::vector<std::uint32_t> m_selection;

    std::optional<QPointF> m_boxStart; ///< Ctrl + drag from empty space: the box's first corner
    bool m_dragging = false;
    bool m_dragMoved = false;
    bool m_alongNormal = false;
    int m_dragFrameCount = 0;
    DragView m_view;
    BrushPick m_grab;                          ///< the grabbed point (object space) and press pixel
    glm::dvec3 m_normal{0.0};                  ///< the selection's average normal (object space)
    std::vector<ControlPointTarget> m_start;   ///< the selection and its tied points at the press
    std::vector<ControlPointTarget> m_targets; ///< the last preview's
    std::unique_ptr<ControlPreview> m_preview;
    std::function<void()> m_restoreView;
    Guard m_guard;
    std::vector<glm::vec3> m_dragReference; ///< dynamic: the current set's reference positions
    DynamicRule m_dragRule = DynamicRule::Confluent;
    double m_lastUpdateMs = 0.0;
    /// The session's subdivision surface's stencils for the viewport's GPU evaluation, and
    /// the definition they were taken from (nullptr: NURBS, or no surface yet).
    std::shared_ptr<const render::SubdivisionStencils> m_gpuStencils;
    std::optional<SubdivisionDefinition> m_gpuStencilsOf;
};

} // namespace trimlab::ui
