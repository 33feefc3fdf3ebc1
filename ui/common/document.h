#pragma once
/// \file
/// One open thing of the main window — a mesh, a scene of several objects, a design
/// history (of a mesh or an editable surface), an animation — with what belongs to it
/// rather than to the user: its view settings (core/timeline/view_settings.h: rule,
/// classification, clipping planes, caps, highlights, X-ray), the project file it is saved
/// to, its undo stack and whether it has changes that no file holds. Preferences — the
/// multi-fragment method and its parameters, panel choices, recent files — stay in the
/// user's settings. A new document is made for every file opened (ui/window/scene_switch.h),
/// so nothing of one file's settings carries over to the next (Blender keeps a file's scene
/// settings apart from its user preferences the same way).
///
/// Every change goes through it: undoable edits are pushed on undoStack() (strokes,
/// control-point edits, set rules, transforms, CSG), changes that cannot be undone mark it
/// changed (markChanged: objects added, a history replayed from a script or recovered
/// after a crash). isModified() is the one state the title's '*', the Save / Discard /
/// Cancel prompt and autosave read; markSaved() follows a save.

#include "core/timeline/view_settings.h"

#include <QObject>
#include <QString>

class QUndoStack;

namespace trimlab::ui {

class Document : public QObject {
    Q_OBJECT
public:
    enum class Kind {
        Mesh,      ///< one object that is not designed (open, untrimmable)
        Scene,     ///< several objects (Add Object, a scene project)
        Design,    ///< a deformation history of one mesh or editable surface
        Animation, ///< a mesh animation (its rest pose shown)
    };

    /// `name` is shown while the document has no project file (a mesh's or demo's display
    /// name); `filePath`, the project file it was read from ("" for none).
    Document(Kind kind, QString name, timeline::DocumentSettings settings, QString filePath = {},
             QObject* parent = nullptr);
    ~Document() override;

    [[nodiscard]] Kind kind() const { return m_kind; }
    /// A design given more objects becomes a scene.
    void setKind(Kind kind) { m_kind = kind; }

    /// What the title shows: the project file's name, else the name given.
    [[nodiscard]] QString title() const;
    /// The name shown while the document has no project file.
    void setName(const QString& name);
    /// The project file (absolute), "" when the document has none (Save asks for one).
    [[nodiscard]] const QString& filePath() const { return m_filePath; }
    void setFilePath(const QString& path);

    [[nodiscard]] const timeline::DocumentSettings& settings() const { return m_settings; }
    /// Emits settingsChanged() when they differ (view settings do not mark it modified:
    /// they are saved with the document, like its camera).
    void setSettings(const timeline::DocumentSettings& settings);

    [[nodiscard]] QUndoStack* undoStack() const { return m_undo; }
    /// Changes no file holds: an undo stack away from its clean state, or markChanged().
    [[nodiscard]] bool isModified() const;
    /// A change that is not on the undo stack.
    void markChanged();
    /// Everything is in the project file `path` now.
    void markSaved(const QString& path);
    /// Increases with every change (an edit, its undo or redo, markChanged): copies such as
    /// autosave's key on it.
    [[nodiscard]] quint64 revision() const { return m_revision; }

signals:
    void modifiedChanged(bool modified);
    /// title() changed.
    void titleChanged();
    void settingsChanged();

private:
    void reportModified();

    Kind m_kind;
    QString m_name;
    QString m_filePath;
    timeline::DocumentSettings m_settings;
    QUndoStack* m_undo;
    bool m_changed = false;
    bool m_reportedModified = false;
    quint64 m_revision = 0;
};

} // namespace trimlab::ui
