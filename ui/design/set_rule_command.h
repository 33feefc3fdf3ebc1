#pragma once
/// \file
/// Undo command of choosing the dynamic rule of one set of concurrent disjoint
/// deformations.

#include "core/trim/dynamic_rule.h"

#include <QUndoCommand>

namespace trimlab::ui {

class DesignSession;

class SetRuleCommand : public QUndoCommand {
public:
    /// Gives set `set` (an index into Timeline::sets()) the rule `rule`.
    SetRuleCommand(DesignSession& session, int set, DynamicRule rule);

    void redo() override;
    void undo() override;

private:
    DesignSession& m_session;
    int m_set;
    DynamicRule m_rule;
    DynamicRule m_previousRule;
};

} // namespace trimlab::ui
