#pragma once
/// \file
/// File ▸ Export Trimmed Solid…: the solid the view shows under its static rule or CSG
/// expression, as exact geometry (core/solid/trimmed_solid.h), computed off the UI thread
/// with a progress dialog and Cancel, written as OBJ, PLY, STL or glTF through a
/// temporary file. Refused with the reason when the view shows no solid (trimming off,
/// an open surface, the dynamic rules of a history). When clipping planes cut the view,
/// the dialog offers the solid as shown — cut by the planes and closed by caps
/// (cutTrimmedSolid) — beside the whole solid.

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
    [[nodiscard]] bool isExporting() const;

signals:
    void exported(const QString& path, const trimlab::TrimmedSolidStats& stats);
    void failed(const QString& path, const QString& message);

private:
    void finish(bool succeeded, const QString& message);
    void closeProgress();

    const WindowContext& m_context;
    ShownSource m_shown;
    BackgroundJob<TrimmedSolidStats>* m_task = nullptr; ///< computes and writes the solid
    QPointer<QProgressDialog> m_progress;
    QString m_path;
};

} // namespace trimlab::ui
