#pragma once
/// \file
/// What the features of the main window ask of the window that shows one thing at a time
/// — a scene, an animation's rest pose, or a design history on a single mesh. The window
/// (ui/window/main_window.h) implements it; feature workspaces read the shown scene and
/// replace it only through it, so how one shown thing gives way to another (pending
/// loads cancelled, the animation and the design session ended, the view reset) stays in
/// one place.

#include "core/catalog/scene_source.h"
#include "core/timeline/timeline.h"

#include <QString>

#include <memory>

namespace trimlab::ui {

class SceneHost {
public:
    virtual ~SceneHost() = default;

    /// The scene shown (nullptr before the first): a mesh, a demo, a project's base mesh
    /// or an animation's rest pose.
    [[nodiscard]] virtual std::shared_ptr<const LoadedScene> shownScene() const = 0;
    /// Shows `history` (a new editable surface: no project file yet) as a design session
    /// on a scene named `name`, in place of whatever is shown and of pending loads. The
    /// caller has asked about unsaved changes.
    virtual void showHistory(timeline::Timeline history, const QString& name) = 0;
    /// Asks about the unsaved work of what is shown before something replaces it: the
    /// design history's changes (Save / Discard / Cancel) and an animation's skinning bone
    /// edits that were not exported (Export… / Discard / Cancel). False: keep what is
    /// shown.
    [[nodiscard]] virtual bool confirmReplacingShown() = 0;
    /// `source` could not be opened for `message`: a dialog, and the window's
    /// sceneLoadFailed(); what is shown stays.
    virtual void reportOpenFailure(const QString& source, const QString& message) = 0;

protected:
    SceneHost() = default;
    SceneHost(const SceneHost&) = default;
    SceneHost& operator=(const SceneHost&) = default;
};

} // namespace trimlab::ui
