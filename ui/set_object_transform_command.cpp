#include "set_object_transform_command.h"

#include "inspect_scene.h"

#include <QCoreApplication>

#include <array>

namespace trimlab::ui {

namespace {

std::array<double, 7> components(const ObjectTransform& t)
{
    return {t.translation.x, t.translation.y, t.translation.z, t.rotationDegrees.x, t.rotationDegrees.y,
            t.rotationDegrees.z, t.scale};
}

} // namespace

int changedTransformComponent(const ObjectTransform& a, const ObjectTransform& b)
{
    const std::array<double, 7> x = components(a);
    const std::array<double, 7> y = components(b);
    int changed = -1;
    for (int i = 0; i < 7; ++i) {
        if (x[std::size_t(i)] == y[std::size_t(i)])
            continue;
        if (changed >= 0)
            return -1;
        changed = i;
    }
    return changed;
}

SetObjectTransformCommand::SetObjectTransformCommand(InspectScene& scene, int object, const ObjectTransform& before,
                                                     const ObjectTransform& after, int dragSession)
    : m_scene(scene), m_object(object), m_before(before), m_after(after),
      m_component(changedTransformComponent(before, after)), m_dragSession(dragSession)
{
    setText(QCoreApplication::translate("SetObjectTransformCommand", "Move object %1").arg(object));
}

void SetObjectTransformCommand::redo()
{
    m_scene.applyTransform(m_object, m_after);
}

void SetObjectTransformCommand::undo()
{
    m_scene.applyTransform(m_object, m_before);
}

bool SetObjectTransformCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = static_cast<const SetObjectTransformCommand*>(other); // same id(): same type
    if (next->m_object != m_object)
        return false;
    const bool sameDrag = m_dragSession >= 0 && next->m_dragSession == m_dragSession;
    const bool sameField = m_dragSession < 0 && next->m_dragSession < 0 && m_component >= 0 &&
                           next->m_component == m_component;
    if (!sameDrag && !sameField)
        return false;
    m_after = next->m_after;
    return true;
}

} // namespace trimlab::ui
