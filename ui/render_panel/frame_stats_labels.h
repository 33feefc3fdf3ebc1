#pragma once
/// \file
/// The permanent labels of the main window's status bar that report each frame: the
/// method, GPU time (ms), fragments in the span, overflowed pixels, unresolved pixels and
/// lost fragments (highlighted when any exist: the method's capacity was too small; the
/// Frame statistics panel offers remedies), the GPU memory the renderer holds (MB), and —
/// while highlighting is on — the pixels highlighted as colliding and as coplanar.

#include "render/frame/frame_counters.h"
#include "core/trim/inspect_settings.h"
#include "render/trim_renderer.h"

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
    /// The highlighted pixels of a frame rendered with `highlight` (hidden when it
    /// highlights nothing): "collisions N px", "coplanar N px".
    void showHighlights(const HighlightSettings& highlight, const render::FrameCounts& counts);
    /// Blank labels (no frame yet, or the renderer failed).
    void clear();

    [[nodiscard]] QLabel* unresolvedLabel() const { return m_unresolved; }
    [[nodiscard]] QLabel* highlightLabel() const { return m_highlights; }

private:
    QLabel* addLabel(QStatusBar* statusBar, const QString& objectName, const QString& toolTip);

    QLabel* m_method;
    QLabel* m_frameTime;
    QLabel* m_fragments;
    QLabel* m_overflow;
    QLabel* m_unresolved;
    QLabel* m_memory;
    QLabel* m_highlights;
};

} // namespace trimlab::ui
