#pragma once
/// \file
/// Opens mesh animations off the UI thread (BackgroundJob on loadAnimationForDisplay),
/// like SceneLoader opens meshes, but with real progress and cancel: the core loader
/// reports one item per file (or sampled glTF pose), shown in a QProgressDialog that
/// appears when loading takes longer than a delay, and its Cancel button stops the
/// loader between files. The dialog is not modal (the window stays usable); a newer
/// open() supersedes a pending one.

#include "ui/common/loaded_animation.h"

#include <QObject>
#include <QPointer>
#include <QString>

#include <memory>

class QProgressDialog;
class QWidget;

namespace trimlab::ui {

class BackgroundJobBase;

class AnimationOpener : public QObject {
    Q_OBJECT
public:
    static constexpr int kDefaultProgressDelayMs = 400;

    /// `dialogParent` is the window the progress dialog is modal to.
    explicit AnimationOpener(QWidget* dialogParent);
    ~AnimationOpener() override;

    /// Starts opening `source` (a folder, a pattern such as dir/mesh_*.obj, or a glTF
    /// file). Exactly one of loaded(), failed() or canceled() follows, unless a newer
    /// open() (which silently stops this one) comes first.
    void open(const QString& source);
    /// Stops the pending load (if any) and emits canceled().
    void cancel();

    /// How long a load runs before its progress dialog appears (ms, >= 0).
    void setProgressDelay(int milliseconds) { m_progressDelayMs = milliseconds > 0 ? milliseconds : 0; }
    /// The progress dialog of the pending load (nullptr when idle); it may still be hidden.
    [[nodiscard]] QProgressDialog* progressDialog() const;
    [[nodiscard]] bool isLoading() const { return m_task != nullptr; }
    [[nodiscard]] QString pendingSource() const { return m_task ? m_source : QString(); }

signals:
    void loaded(std::shared_ptr<const trimlab::ui::LoadedAnimation> animation);
    /// `message` is the loader's reason (MeshLoadError: "FILE[:LINE]: REASON").
    void failed(const QString& source, const QString& message);
    void canceled(const QString& source);

private:
    void abandonTask();
    void showProgress(const QString& source);
    void updateProgress(const QString& stage, qint64 done, qint64 total);
    void closeProgress();
    void finishLoad(std::shared_ptr<const LoadedAnimation> animation);
    void failLoad(const QString& message);

    QWidget* m_dialogParent;
    QPointer<QProgressDialog> m_progress;
    /// The pending load's job (nullptr when idle); abandoned jobs delete themselves.
    BackgroundJobBase* m_task = nullptr;
    QString m_source;
    int m_progressDelayMs = kDefaultProgressDelayMs;
};

} // namespace trimlab::ui
