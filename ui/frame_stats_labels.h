#pragma once
/// \file
/// The permanent labels of the main window's status bar that report each frame: GPU time
/// (ms), fragments stored, overflowed and unresolved pixels (the latter highlighted when
/// any exist: those pixels show magenta because k was too small), and the GPU memory
/// the renderer holds (MB).

#include "frame_counters.h"
#include "trim_renderer.h"

#include <QObject>

class QLabel;
class QStatusBar;

namespace trimlab::ui {

class FrameStatsLabels : public QObject {
    Q_OBJECT
public:
    /// Adds the labels to `statusBar` as permanent widgets (right-aligned).
    explicit FrameStatsLabels(QStatusBar* statusBar);

    void showStats(const render::FrameStats& stats);
    /// Blank labels (no frame yet, or the renderer failed).
    void clear();

    [[nodiscard]] QLabel* unresolvedLabel() const { return m_unresolved; }

private:
    QLabel* addLabel(QStatusBar* statusBar, const QString& objectName, const QString& toolTip);

    QLabel* m_frameTime;
    QLabel* m_fragments;
    QLabel* m_overflow;
    QLabel* m_unresolved;
    QLabel* m_memory;
};

} // namespace trimlab::ui
