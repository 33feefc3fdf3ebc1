#include "ui/design/append_frame_command.h"

#include "ui/design/design_session.h"

namespace trimlab::ui {

AppendFrameCommand::AppendFrameCommand(DesignSession& session, timeline::Frame frame, const QString& what)
    : m_session(session), m_frame(std::move(frame))
{
    setText(what);
}

void AppendFrameCommand::redo()
{
    m_session.appendFrame(m_frame);
}

void AppendFrameCommand::undo()
{
    m_frame = m_session.removeLastFrame();
}

} // namespace trimlab::ui
