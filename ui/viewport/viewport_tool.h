#pragma once
/// \file
/// A mouse tool the viewport hands its mouse events to before its own camera handling
/// (the brush is one). The viewport asks the tool first on every press; a press the tool
/// takes is followed by moved() for each motion and released() when the last button goes
/// up. Without a button down the tool sees hovered(), and left() when the cursor leaves
/// the view. Positions are the events' logical widget coordinates.

#include <QPointF>
#include <QString>

class QMouseEvent;

namespace trimlab::ui {

class ViewportTool {
public:
    virtual ~ViewportTool() = default;
    /// True when the tool takes this press (the camera then does not move).
    virtual bool pressed(QMouseEvent& event) = 0;
    virtual void moved(QMouseEvent& event) = 0;
    virtual void released(QMouseEvent& event) = 0;
    virtual void hovered(QPointF position) = 0;
    virtual void left() = 0;
    /// What the mouse does in the view while the tool is on: the viewport's tooltip.
    [[nodiscard]] virtual QString mouseHelp() const = 0;

protected:
    ViewportTool() = default;
    ViewportTool(const ViewportTool&) = default;
    ViewportTool& operator=(const ViewportTool&) = default;
};

} // namespace trimlab::ui
