#pragma once
/// \file
/// The brush as a viewport tool (thesis 8.2's space-warp brush). With the tool on:
/// - left drag on the surface deforms the last frame: the press grabs the surface point
///   under the cursor (read from the last frame's trim image), each move drags it in the
///   view plane at the grabbed depth (with Shift: along the grabbed triangle's normal,
///   cursor up pulls out), and the release records the stroke as one undoable frame;
///   a click without movement records nothing;
/// - a press on the background, Alt + left drag, right and middle drag still move the
///   camera (the viewport handles what the tool declines);
/// - hovering the surface tints the geodesic region the brush would move, by falloff
///   weight (static rule only: the dynamic-rule scenes carry no vertex colors). The
///   region is recomputed only when the hovered triangle changes, at most every
///   kHoverIntervalMs.
/// On an editable surface's history (DesignSession::surface()) the brush moves control
/// points instead of mesh vertices (ControlBrushDrag: every control point within the
/// radius of the grabbed point, by the falloff), records the drag as one control edit
/// (AppendFrameCommand), and hovering tints nothing (the geodesic mesh region is not what
/// moves). The control guard judges the finished edit's frame (the moved vertices are
/// known only then).
/// On an earlier frame than the last, or when a guard (the homogeneous confluent rule)
/// refuses the grabbed region, the press is refused with a status message saying why.

#include "render/content_publisher.h"

#include "core/design/brush_drag.h"
#include "core/deform/stroke.h"
#include "core/trim/dynamic_chain.h"
#include "ui/viewport/viewport_tool.h"

#include <QObject>
#include <QPointer>
#include <QTimer>

#include <functional>
#include <memory>
#include <optional>

namespace trimlab::ui {

class ControlBrushDrag;
class DesignSession;
class ViewportWidget;

class BrushTool : public QObject, public ViewportTool {
    Q_OBJECT
public:
    static constexpr int kHoverIntervalMs = 40;
    /// Decides whether a drag may start; returns the reason to refuse, or nullopt.
    using Guard = std::function<std::optional<QString>(const BrushDrag& drag)>;

    explicit BrushTool(ViewportWidget* viewport, QObject* parent = nullptr);
    ~BrushTool() override;

    /// The history to edit (nullptr: the tool declines every press). While on, the tool
    /// leaves the viewport without a history (its mouse and tooltip are the camera's) and
    /// takes it back, unless another tool has it, when a history comes.
    void setSession(DesignSession* session);
    void setSettings(const deform::BrushSettings& settings);
    [[nodiscard]] const deform::BrushSettings& settings() const { return m_settings; }
    /// Installed on the viewport while on and a history is edited; off clears the region
    /// tint.
    void setEnabled(bool enabled);
    [[nodiscard]] bool isEnabled() const { return m_enabled; }
    /// Whether the design history is shown under the dynamic rules (drags then replace the
    /// shown level of its chain).
    void setDynamicRules(bool dynamic);
    void setGuard(Guard guard) { m_guard = std::move(guard); }
    /// The guard of a brush drag on control points, judged on the finished edit's frame.
    using ControlGuard = std::function<std::optional<QString>(const timeline::Frame& frame)>;
    void setControlGuard(ControlGuard guard) { m_controlGuard = std::move(guard); }

    [[nodiscard]] bool isDragging() const { return m_drag != nullptr || m_controlDrag != nullptr; }
    /// Milliseconds the last drag update took in the UI thread: the stroke update plus
    /// handing the positions (static) or the rebuilt shown level (dynamic) to the viewport.
    [[nodiscard]] double lastUpdateMilliseconds() const { return m_lastUpdateMs; }

    bool pressed(QMouseEvent& event) override;
    void moved(QMouseEvent& event) override;
    void released(QMouseEvent& event) override;
    void hovered(QPointF position) override;
    void left() override;
    [[nodiscard]] QString mouseHelp() const override;

signals:
    void statusMessage(const QString& message);

private:
    [[nodiscard]] std::optional<BrushPick> pickAt(QPointF position);
    [[nodiscard]] std::optional<QString> refusalBeforePick() const;
    void showDragPositions(const std::vector<glm::vec3>& positions);
    void rememberDragStart();
    bool startControlDrag(const BrushPick& pick);
    void releaseControlDrag();
    [[nodiscard]] DynamicChainLevel dynamicShownLevelOf(const std::vector<glm::vec3>& positions) const;
    void updateHoverRegion();
    void clearRegionTint();

    ViewportWidget* m_viewport;
    render::ContentPublisher m_shown; ///< drags: the design history's pose and shown level
    render::ContentPublisher m_tint;  ///< the hovered region's colours
    QPointer<DesignSession> m_session;
    deform::BrushSettings m_settings;
    bool m_enabled = false;
    bool m_dynamic = false;
    Guard m_guard;
    ControlGuard m_controlGuard;
    std::unique_ptr<BrushDrag> m_drag;
    std::unique_ptr<ControlBrushDrag> m_controlDrag; ///< on an editable surface
    int m_dragFrameCount = 0;                        ///< the history's frame count at the press
    std::vector<glm::vec3> m_dragReference;          ///< dynamic: the current set's reference positions
    DynamicRule m_dragRule = DynamicRule::Confluent;
    double m_lastUpdateMs = 0.0;
    QTimer m_hoverTimer;
    QPointF m_hoverPosition;
    std::optional<std::uint32_t> m_hoverTriangle;
    bool m_tinted = false;
};

} // namespace trimlab::ui
