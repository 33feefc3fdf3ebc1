#include "ui/design/set_rule_command.h"

#include "ui/design/design_session.h"

#include <QCoreApplication>

namespace trimlab::ui {

SetRuleCommand::SetRuleCommand(DesignSession& session, int set, DynamicRule rule)
    : m_session(session), m_set(set), m_rule(rule), m_previousRule(session.timeline().sets().at(std::size_t(set)).rule)
{
    const std::string_view name = dynamicRuleDisplayName(rule);
    setText(QCoreApplication::translate("SetRuleCommand", "Set %1 rule: %2")
                .arg(set + 1)
                .arg(QString::fromUtf8(name.data(), qsizetype(name.size()))));
}

void SetRuleCommand::redo()
{
    m_session.setRule(m_set, m_rule);
}

void SetRuleCommand::undo()
{
    m_session.setRule(m_set, m_previousRule);
}

} // namespace trimlab::ui
