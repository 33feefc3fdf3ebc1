#pragma once
/// \file
/// "Measure all methods": renders the viewport's current view with every method of
/// render::fragmentMethods() a few times, one method per event-loop turn so the window
/// stays responsive, and collects each method's median time per frame (or why it failed).

#include "render/mfr/fragment_method.h"

#include <QObject>
#include <QPointer>
#include <QString>

#include <optional>
#include <vector>

namespace trimlab::ui {

class ViewportWidget;

/// One method's result on the surveyed view.
struct MethodTiming {
    render::FragmentMethodKind method = render::FragmentMethodKind::KPlusArray;
    std::optional<double> milliseconds; ///< median per frame; nullopt when it failed
    QString timeSource;                 ///< "GPU" or "wall"
    QString failure;                    ///< why it has no time
    int geometryPasses = 0;
    double megabytes = 0.0;
    std::uint64_t fragmentsLost = 0;
};

class MethodSurvey : public QObject {
    Q_OBJECT
public:
    explicit MethodSurvey(ViewportWidget* viewport, QObject* parent = nullptr);

    /// Starts measuring every method with `framesPerMethod` timed frames each (after one
    /// warm-up frame); restarts when already running.
    void start(int framesPerMethod = 3);
    /// Stops after the method being measured; emits finished() with what was measured.
    void cancel();
    [[nodiscard]] bool isRunning() const { return m_running; }
    [[nodiscard]] const std::vector<MethodTiming>& results() const { return m_results; }

signals:
    /// `done` of `total` methods measured.
    void progress(int done, int total);
    void finished();

private:
    void measureNext();
    void finish();

    QPointer<ViewportWidget> m_viewport;
    std::vector<MethodTiming> m_results;
    int m_framesPerMethod = 3;
    std::size_t m_next = 0;
    bool m_running = false;
    int m_generation = 0; ///< invalidates turns queued before a restart or cancel
};

} // namespace trimlab::ui
