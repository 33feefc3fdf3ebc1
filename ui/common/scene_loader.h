#pragma once
/// \file
/// Loads scenes off the UI thread: QtConcurrent::run on loadScene (scene_source.h), with a
/// busy QProgressDialog that appears only when a load takes longer than a delay
/// (kDefaultProgressDelayMs). Cancel — or a newer load() — discards the pending result: loadScene
/// cannot be interrupted, so its worker runs to the end in the background and what it
/// returns is dropped, never shown.

#include "core/catalog/scene_source.h"

#include <QObject>
#include <QPointer>
#include <QString>

#include <memory>

class QProgressDialog;
class QWidget;

namespace trimlab::ui {

class SceneLoader : public QObject {
    Q_OBJECT
public:
    static constexpr int kDefaultProgressDelayMs = 400;

    /// `dialogParent` is the window the progress dialog is modal to.
    explicit SceneLoader(QWidget* dialogParent);
    ~SceneLoader() override;

    /// Starts loading `source` (a file path or "demo:NAME"). A load still pending is
    /// discarded silently. Exactly one of loaded(), failed() or canceled() follows for
    /// this source, unless a newer load() supersedes it.
    void load(const QString& source);
    /// Discards the pending load (if any) and emits canceled().
    void cancel();

    /// How long a load runs before its progress dialog appears (ms, >= 0); applies to
    /// later load() calls.
    void setProgressDelay(int milliseconds) { m_progressDelayMs = milliseconds > 0 ? milliseconds : 0; }
    /// The progress dialog of the pending load (nullptr when idle); it may still be hidden.
    [[nodiscard]] QProgressDialog* progressDialog() const;

    [[nodiscard]] bool isLoading() const { return m_pending; }
    /// The source of the pending load; empty when idle.
    [[nodiscard]] QString pendingSource() const { return m_pending ? m_source : QString(); }

signals:
    void loaded(std::shared_ptr<const trimlab::LoadedScene> scene);
    /// `message` is the loader's reason, e.g. MeshLoadError::what() ("FILE:LINE: REASON").
    void failed(const QString& source, const QString& message);
    void canceled(const QString& source);

private:
    void showProgress(const QString& source);
    void closeProgress();
    void finish(std::shared_ptr<const LoadedScene> scene, const QString& error, quint64 generation);

    QWidget* m_dialogParent;
    QPointer<QProgressDialog> m_progress;
    QString m_source;
    quint64 m_generation = 0;
    int m_progressDelayMs = kDefaultProgressDelayMs;
    bool m_pending = false;
};

} // namespace trimlab::ui
