#include "ui/design/start_set_command.h"

#include "ui/design/design_session.h"

#include <QCoreApplication>

namespace trimlab::ui {

StartSetCommand::StartSetCommand(DesignSession& session, DynamicRule rule) : m_session(session), m_rule(rule)
{
    const std::string_view name = dynamicRuleDisplayName(rule);
    setText(QCoreApplication::translate("StartSetCommand", "New set (%1)")
                .arg(QString::fromUtf8(name.data(), qsizetype(name.size()))));
}

void StartSetCommand::redo()
{
    const timeline::DeformationSet& last = m_session.timeline().sets().back();
    m_renamedEmptySet = last.frameCount == 0;
    m_previousRule = last.rule;
    m_session.startSet(m_rule);
}

void StartSetCommand::undo()
{
    if (m_renamedEmptySet)
        m_session.setRule(m_session.currentSet(), m_previousRule);
    else
        m_session.removeLastSetIfEmpty();
}

} // namespace trimlab::ui
