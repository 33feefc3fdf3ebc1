#pragma once
/// \file
/// File ▸ Export Trimmed Solid…: the solid the view shows under its static rule or CSG
/// expression, as exact geometry (core/solid/trimmed_solid.h), computed off the UI thread
/// with a progress dialog and Cancel, written as OBJ, PLY, STL or glTF through a
/// temporary file. Refused with the reason when the view shows no solid (trimming off,
/// an open surface, the dynamic rules of a history). When clipping planes cut the view,
/// the dialog offers the solid as shown — cut by the planes and closed by caps
/// (cutTrimmedSolid) — beside the whole solid. When the view shows an animation of
/// several poses, it offers the pose shown or every pose, each trimmed on its own
/// (core/solid/trimmed_animation.h), as one glTF that plays them in turn at the
/// Timeline's rate (core/mesh/mesh_sequence_gltf.h), with the poses' progress.

#include "core/animation/mesh_animation.h"
#include "core/scene/scene.h"
#include "core/solid/trimmed_solid.h"
#include "core/trim/trim_settings.h"

#include <QObject>
#include <QPointer>
#include <QString>

#include <functional>
#include <memory>

class QProgressDialog;

namespace trimlab::ui {

template <class T>
class BackgroundJob;
class WindowContext;

class SolidExport : public QObject {
    Q_OBJECT
public:
    /// What the view shows: the scene and the settings it is trimmed with, or why it has
    /// no solid to export (`refusal` not empty) and what the user can do about it. The
    /// refusal is the message's first line: the reason comes before anything generic.
    struct Shown {
        std::shared_ptr<const Scene> scene;
        TrimSettings settings;
        QString name;    ///< suggests the file name
        QString refusal; ///< the reason, one sentence
        QString remedy;  ///< what to change to get a solid; may be empty
        /// The animation shown (every pose can be exported), else null; `pose` is the
        /// one shown, `fps` the Timeline's rate.
        std::shared_ptr<const MeshAnimation> animation;
        int pose = 0;
        double fps = 24.0;
    };
    using ShownSource = std::function<Shown()>;

    SolidExport(const WindowContext& context, ShownSource shown, QObject* parent = nullptr);
    ~SolidExport() override;

    /// What is exported of the solid shown.
    enum class Extent {
        Whole,   ///< trimmedSolid: the clipping planes play no part
        AsShown, ///< cutTrimmedSolid: cut by the enabled clipping planes and capped
    };

    /// Asks which extent (when clipping planes are on) and for the file, then exportTo().
    void showExportDialog();
    /// Starts the export of what is shown to `path` (its extension picks the format);
    /// exported() or failed() follows, nothing when canceled. A refusal is shown at once
    /// and reported through failed().
    void exportTo(const QString& path, Extent extent = Extent::Whole);
    /// Starts the export of every pose of the animation shown to the glTF `path` (.glb or
    /// .gltf); posesExported() or failed() follows. Refused as exportTo() is, and when no
    /// animation is shown.
    void exportPosesTo(const QString& path, Extent extent = Extent::Whole);
    [[nodiscard]] bool isExporting() const;

signals:
    void exported(const QString& path, const trimlab::TrimmedSolidStats& stats);
    /// Every pose written: how many, and the sum of their volumes.
    void posesExported(const QString& path, std::size_t poses, double totalVolume);
    void failed(const QString& path, const QString& message);

public:
    /// What one export wrote: one solid's statistics, or a sequence of poses.
    struct Written {
        TrimmedSolidStats stats; ///< of the one solid, or of the last pose
        std::size_t poses = 0;   ///< 0: one solid
        double totalVolume = 0.0;
    };

private:
    /// Refuses (message and failed()) when nothing can be exported now; true when it did.
    bool refused(const Shown& shown, const QString& path);
    void finish(bool succeeded, const QString& message);
    void closeProgress();

    const WindowContext& m_context;
    ShownSource m_shown;
    BackgroundJob<Written>* m_task = nullptr; ///< computes and writes the solid or the poses
    QPointer<QProgressDialog> m_progress;
    QString m_path;
};

} // namespace trimlab::ui
