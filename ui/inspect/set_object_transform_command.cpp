#include "ui/inspect/set_object_transform_command.h"

#include "ui/inspect/inspect_scene.h"

#include <QCoreApplication>

#include <array>

namespace trimlab::ui {

namespace {

std::array<double, 7> components(const ObjectTransform& t)
{
    return {t.translation.x,     t.translation.y,     t.translation.z, t.rotationDegrees.x,
            t.rotationDegrees.y, t.rotationDegrees.z, t.scale};
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
    : InspectSceneValueCommand(scene, before, after, dragSession),
      m_object(object),
      m_component(changedTransformComponent(before, after))
{
    setText(QCoreApplication::translate("SetObjectTransformCommand", "Move object %1").arg(object));
}

void SetObjectTransformCommand::apply(const ObjectTransform& transform)
{
    m_scene.applyTransform(m_object, transform);
}

bool SetObjectTransformCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = static_cast<const SetObjectTransformCommand*>(other); // same id(): same type
    if (next->m_object != m_object)
        return false;
    const bool sameDrag = sameSession(*next);
    const bool sameField = session() < 0 && next->session() < 0 && m_component >= 0 && next->m_component == m_component;
    if (!sameDrag && !sameField)
        return false;
    takeAfter(*next);
    return true;
}

} // namespace trimlab::ui
