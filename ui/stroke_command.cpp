#include "stroke_command.h"

#include "design_session.h"

#include <QCoreApplication>

namespace trimlab::ui {

StrokeCommand::StrokeCommand(DesignSession& session, timeline::Frame frame)
    : m_session(session), m_frame(std::move(frame))
{
    setText(QCoreApplication::translate("StrokeCommand", "Stroke (%n vertices)", nullptr,
                                        int(m_frame.vertices.size())));
}

void StrokeCommand::redo()
{
    m_session.appendFrame(m_frame);
}

void StrokeCommand::undo()
{
    m_frame = m_session.removeLastFrame();
}

} // namespace trimlab::ui
