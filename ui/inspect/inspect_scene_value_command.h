#pragma once
/// \file
/// The shared shape of the Inspect scene's undo commands (SetCsgCommand,
/// SetObjectTransformCommand): each swaps one value of the InspectScene between the value
/// before the edit (undo) and after it (redo), and the commands of one editing session (a
/// drag in the viewport, one typed expression) merge into one undo step.

#include <QUndoCommand>

namespace trimlab::ui {

class InspectScene;

/// Undo command that holds a `Value` of the scene before and after one edit. The derived
/// command writes a value with apply() (an InspectScene::apply… call, which sets without
/// recording) and decides in mergeWith() when two edits are one step. `Id` is the
/// QUndoCommand::id() merge key: one per derived type, so that mergeWith() may cast its
/// argument to the derived type (QUndoStack only merges commands of equal id()).
template <typename Value, int Id>
class InspectSceneValueCommand : public QUndoCommand {
public:
    static constexpr int kId = Id;

    void redo() final { apply(m_after); }
    void undo() final { apply(m_before); }
    [[nodiscard]] int id() const final { return kId; }

protected:
    /// `session` >= 0: the editing session (drag, typing) the command belongs to; −1: none.
    InspectSceneValueCommand(InspectScene& scene, const Value& before, const Value& after, int session)
        : m_scene(scene), m_before(before), m_after(after), m_session(session)
    {
    }

    /// Writes `value` into the scene without recording an undo step.
    virtual void apply(const Value& value) = 0;

    /// The editing session given at construction, −1 for none.
    [[nodiscard]] int session() const { return m_session; }
    /// True when both commands are steps of the same session; never for −1.
    [[nodiscard]] bool sameSession(const InspectSceneValueCommand& next) const
    {
        return m_session >= 0 && next.m_session == m_session;
    }
    /// Merging `next` into this command: redo now ends at `next`'s value; undo still
    /// returns to this command's value before.
    void takeAfter(const InspectSceneValueCommand& next) { m_after = next.m_after; }

    InspectScene& m_scene;

private:
    Value m_before;
    Value m_after;
    int m_session;
};

} // namespace trimlab::ui
