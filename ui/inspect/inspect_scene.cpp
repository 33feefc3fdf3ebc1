#include "ui/inspect/inspect_scene.h"

#include "ui/inspect/set_csg_command.h"
#include "ui/inspect/set_object_transform_command.h"

#include <QUndoStack>

namespace trimlab::ui {

InspectScene::InspectScene(QObject* parent) : QObject(parent), m_ownUndoStack(new QUndoStack(this))
{
    m_ownUndoStack->setObjectName(QStringLiteral("inspectUndoStack"));
    m_undoStack = m_ownUndoStack;
}

InspectScene::~InspectScene() = default;

void InspectScene::reset(std::shared_ptr<const LoadedScene> scene, QUndoStack* undoStack)
{
    if (m_undoStack)          // gone with its document, or still here:
        m_undoStack->clear(); // its commands refer to the previous scene's objects
    m_undoStack = undoStack ? undoStack : m_ownUndoStack;
    m_undoStack->clear();
    m_scene = std::move(scene);
    m_transforms.clear();
    if (m_scene)
        for (const SceneObject& object : m_scene->scene.objects)
            m_transforms.push_back(decomposeObjectTransform(object.modelMatrix));
    m_csg = m_scene ? m_scene->savedCsg : CsgSettings{}; // a scene project's CSG, else none
    emit sceneReplaced();
    emit csgChanged();
}

bool InspectScene::appendObjects(const LoadedScene& added, QString* error)
{
    QString reason;
    const std::size_t total = (m_scene ? m_scene->scene.objects.size() : 0) + added.scene.objects.size();
    if (!m_scene)
        reason = tr("There is no scene to add objects to; open one first.");
    else if (total > Scene::maxObjects)
        reason =
            tr("The scene would have %1 objects; the renderer supports at most %2.").arg(total).arg(Scene::maxObjects);
    if (!reason.isEmpty()) {
        if (error)
            *error = reason;
        return false;
    }
    auto grown = std::make_shared<LoadedScene>(*m_scene);
    for (std::size_t i = 0; i < added.scene.objects.size(); ++i) {
        grown->scene.objects.push_back(added.scene.objects[i]);
        if (i < added.reports.size())
            grown->reports.push_back(added.reports[i]);
        m_transforms.push_back(decomposeObjectTransform(added.scene.objects[i].modelMatrix));
    }
    m_scene = std::move(grown);
    emit sceneReplaced();
    return true;
}

int InspectScene::objectCount() const
{
    return m_scene ? int(m_scene->scene.objects.size()) : 0;
}

std::optional<ObjectTransform> InspectScene::transform(int object) const
{
    if (object < 0 || std::size_t(object) >= m_transforms.size())
        return std::nullopt;
    return m_transforms[std::size_t(object)];
}

void InspectScene::editTransform(int object, const ObjectTransform& transform, bool dragging)
{
    const std::optional<ObjectTransform> before = this->transform(object);
    if (!before || *before == transform)
        return;
    m_undoStack->push(new SetObjectTransformCommand(*this, object, *before, transform, dragging ? m_dragSession : -1));
}

void InspectScene::editCsg(const CsgSettings& csg, const QString& description, bool typing)
{
    if (csg == m_csg)
        return;
    m_undoStack->push(new SetCsgCommand(*this, m_csg, csg, description, typing ? m_typingSession : -1));
}

void InspectScene::applyTransform(int object, const ObjectTransform& transform)
{
    if (!this->transform(object) || !m_scene)
        return;
    m_transforms[std::size_t(object)] = transform;
    auto moved = std::make_shared<LoadedScene>(*m_scene);
    moved->scene.objects[std::size_t(object)].modelMatrix = transform.modelMatrix();
    m_scene = std::move(moved);
    emit transformChanged(object);
}

void InspectScene::applyCsg(const CsgSettings& csg)
{
    m_csg = csg;
    emit csgChanged();
}

} // namespace trimlab::ui
