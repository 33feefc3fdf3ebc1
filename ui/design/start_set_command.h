#pragma once
/// \file
/// Undo command of "New set": starts a set of concurrent disjoint deformations whose
/// reference is the current last frame. When the last set has no stroke yet,
/// Timeline::startSet only changes that set's rule; undo then restores the old rule
/// instead of removing a set.

#include "core/trim/dynamic_rule.h"

#include <QUndoCommand>

namespace trimlab::ui {

class DesignSession;

class StartSetCommand : public QUndoCommand {
public:
    StartSetCommand(DesignSession& session, DynamicRule rule);

    void redo() override;
    void undo() override;

private:
    DesignSession& m_session;
    DynamicRule m_rule;
    bool m_renamedEmptySet = false; ///< what redo did, for undo
    DynamicRule m_previousRule = DynamicRule::Confluent;
};

} // namespace trimlab::ui
