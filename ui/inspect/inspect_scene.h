#pragma once
/// \file
/// The scene shown, under the Scene panel's edits: each object's transform (translation,
/// rotation in degrees, uniform scale: core/scene/object_transform.h) and the CSG
/// settings (the expression over object ids and per-object rules: core/trim). Holds no
/// algorithm; it keeps the current values, records edits on the undo stack of the
/// document shown (ui/common/document.h: the window's Edit ▸ Undo/Redo; whether it is
/// modified is the document's) and says what changed.
///
/// The scene is a value: every transform edit replaces it by a copy whose one model
/// matrix differs (meshes copied, so whoever holds the previous scene — the viewport's
/// last frame, a test's reference renderer — keeps a consistent one). Adding objects
/// (File ▸ Add Object…) appends them; it is not undoable, and the edits recorded before
/// stay valid because object ids never change.

#include "core/scene/object_transform.h"
#include "core/catalog/scene_source.h"
#include "core/trim/inspect_settings.h"

#include <QObject>
#include <QPointer>
#include <QUndoStack>
#include <QString>

#include <memory>
#include <optional>
#include <vector>

namespace trimlab::ui {

class InspectScene : public QObject {
    Q_OBJECT
public:
    explicit InspectScene(QObject* parent = nullptr);
    ~InspectScene() override;

    /// A newly opened scene (nullptr: none): transforms read from its model matrices, the
    /// CSG and per-object rules a scene project saved (else none); edits go on `undoStack`
    /// (its document's, emptied here; nullptr: a stack of this object's own). Emits
    /// sceneReplaced().
    void reset(std::shared_ptr<const LoadedScene> scene, QUndoStack* undoStack = nullptr);
    /// Appends the objects of `added` (their names, meshes, model matrices and validation
    /// reports) to the scene. Emits sceneReplaced(). False with the reason in `error`
    /// when there is no scene or the result would exceed Scene::maxObjects objects.
    bool appendObjects(const LoadedScene& added, QString* error);

    [[nodiscard]] const std::shared_ptr<const LoadedScene>& scene() const { return m_scene; }
    [[nodiscard]] int objectCount() const;
    /// Object `object`'s transform; nullopt when its model matrix is not a rotation,
    /// uniform scale and translation (such an object cannot be edited numerically) or the
    /// index is out of range.
    [[nodiscard]] std::optional<ObjectTransform> transform(int object) const;
    [[nodiscard]] const CsgSettings& csg() const { return m_csg; }
    /// The stack edits go on (reset()).
    [[nodiscard]] QUndoStack* undoStack() const { return m_undoStack.data(); }

    /// Undoable: moves object `object` to `transform`. Consecutive edits of the same
    /// component of one object (spin box steps) merge into one undo step, and so do the
    /// edits of one drag in the viewport (`dragging` true, until endDrag()). Ignored for
    /// an object without a transform() or when nothing changes.
    void editTransform(int object, const ObjectTransform& transform, bool dragging = false);
    /// Ends the merging of a drag's edits.
    void endDrag() { ++m_dragSession; }
    /// Undoable: new CSG settings; `description` names the step in the Edit menu. Edits
    /// made with `typing` true merge until endTyping() (each valid keystroke of the
    /// expression field renders at once, one undo step per typed expression). Ignored
    /// when nothing changes.
    void editCsg(const CsgSettings& csg, const QString& description, bool typing = false);
    /// Ends the merging of typed CSG edits.
    void endTyping() { ++m_typingSession; }

    /// Used by the undo commands: sets the value without recording it.
    void applyTransform(int object, const ObjectTransform& transform);
    void applyCsg(const CsgSettings& csg);

signals:
    /// Another scene (reset) or more objects (appendObjects).
    void sceneReplaced();
    /// Object `object`'s model matrix changed (scene() is the new scene).
    void transformChanged(int object);
    void csgChanged();

private:
    std::shared_ptr<const LoadedScene> m_scene;
    std::vector<std::optional<ObjectTransform>> m_transforms;
    CsgSettings m_csg;
    QUndoStack* m_ownUndoStack;
    QPointer<QUndoStack> m_undoStack; ///< the document's, which may go first
    int m_typingSession = 0;
    int m_dragSession = 0;
};

} // namespace trimlab::ui
