#pragma once
/// \file
/// The undo command of every edit that adds a frame to the deformation history: a brush
/// stroke on the mesh, or a control-point edit of a NURBS or subdivision surface (a drag,
/// the brush on control points, a move along the normal). Redo appends the frame, undo
/// removes it again, bit for bit (DesignSession, timeline::Timeline).

#include "core/timeline/timeline.h"

#include <QString>
#include <QUndoCommand>

namespace trimlab::ui {

class DesignSession;

class AppendFrameCommand : public QUndoCommand {
public:
    /// `frame` must continue the session's last frame (Timeline::appendFrame's rules).
    /// `what` names the edit in the Edit menu ("Stroke (120 vertices)", "Move 3 control
    /// points").
    AppendFrameCommand(DesignSession& session, timeline::Frame frame, const QString& what);

    /// Appends the frame (the first redo happens when the command is pushed).
    void redo() override;
    /// Removes it again.
    void undo() override;

private:
    DesignSession& m_session;
    timeline::Frame m_frame;
};

} // namespace trimlab::ui
