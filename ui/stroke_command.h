#pragma once
/// \file
/// Undo command of one brush stroke. The frame holds the exact before/after positions of
/// the vertices the stroke changed, so undo restores the previous positions bit for bit
/// and redo re-applies exactly what the drag produced (nothing is recomputed).

#include "timeline/timeline.h"

#include <QUndoCommand>

namespace trimlab::ui {

class DesignSession;

class StrokeCommand : public QUndoCommand {
public:
    /// `frame` must continue the session's last frame (Timeline::appendFrame's rules).
    StrokeCommand(DesignSession& session, timeline::Frame frame);

    /// Appends the frame (the first redo happens when the command is pushed).
    void redo() override;
    /// Removes it again.
    void undo() override;

private:
    DesignSession& m_session;
    timeline::Frame m_frame;
};

} // namespace trimlab::ui
