#include "ui/render_panel/frame_stats_labels.h"

#include <QLabel>
#include <QLocale>
#include <QStringList>
#include <QStatusBar>

namespace trimlab::ui {

namespace {

/// "12,345" below a million, "1.23 M" above.
QString countText(std::uint64_t count)
{
    if (count < 1000000)
        return QLocale().toString(qulonglong(count));
    return QStringLiteral("%1 M").arg(double(count) / 1e6, 0, 'f', 2);
}

} // namespace

FrameStatsLabels::FrameStatsLabels(QStatusBar* statusBar) : QObject(statusBar)
{
    m_method = addLabel(statusBar, QStringLiteral("methodLabel"), tr("The multi-fragment method of the last frame"));
    m_frameTime = addLabel(statusBar, QStringLiteral("frameTimeLabel"),
                           tr("GPU time of the last frame (clear, store and resolve passes)"));
    m_fragments = addLabel(statusBar, QStringLiteral("fragmentsLabel"),
                           tr("Fragments inside the kept span (after clipping) in the last frame"));
    m_overflow =
        addLabel(statusBar, QStringLiteral("overflowLabel"), tr("Pixels that lost fragments to the method's capacity"));
    m_unresolved = addLabel(statusBar, QStringLiteral("unresolvedLabel"),
                            tr("Overflowed pixels whose trim point may have been lost (they show magenta) and "
                               "fragments lost. The Frame statistics panel offers a larger k or an unbounded method."));
    m_memory = addLabel(statusBar, QStringLiteral("memoryLabel"),
                        tr("GPU memory held by the multi-fragment method, the render target and the scene"));
    m_highlights = addLabel(statusBar, QStringLiteral("highlightLabel"),
                            tr("Pixels of the last frame highlighted as colliding (inside another object, or where an "
                               "object overlaps itself) and as coplanar (sharing their depth with other surfaces)"));
    clear();
}

QLabel* FrameStatsLabels::addLabel(QStatusBar* statusBar, const QString& objectName, const QString& toolTip)
{
    auto* label = new QLabel(statusBar);
    label->setObjectName(objectName);
    label->setToolTip(toolTip);
    label->setContentsMargins(6, 0, 6, 0);
    statusBar->addPermanentWidget(label);
    return label;
}

void FrameStatsLabels::showStats(const render::FrameStats& stats)
{
    const std::string_view name = render::methodInfo(stats.method).displayName;
    m_method->setText(QString::fromUtf8(name.data(), qsizetype(name.size())));
    // The GPU timer can be unavailable (llvmpipe's first query); the wall time, which
    // includes waiting for the GPU, is then the honest number.
    m_frameTime->setText(stats.gpuMilliseconds >= 0.0 ? tr("GPU %1 ms").arg(stats.gpuMilliseconds, 0, 'f', 1)
                                                      : tr("frame %1 ms").arg(stats.wallMilliseconds, 0, 'f', 1));
    m_fragments->setText(tr("%1 fragments").arg(countText(stats.counts.fragmentsInSpan)));
    m_overflow->setText(tr("overflow %1 px").arg(countText(stats.counts.overflowPixels)));
    const std::uint64_t unresolved = stats.counts.unresolvedPixels;
    const std::uint64_t lost = stats.counts.fragmentsLost;
    const std::uint64_t dropped = stats.counts.spinGiveUps;
    QString text = tr("unresolved %1 px").arg(countText(unresolved));
    if (lost > 0) // capacity or the bounded spin-lock: the image may be incomplete
        text += tr(", %1 fragments lost").arg(countText(lost));
    if (dropped > 0)
        text += tr(" (%1 gave up on the spin-lock)").arg(countText(dropped));
    m_unresolved->setText(text);
    const bool overflowing = unresolved > 0 || lost > 0 || dropped > 0;
    m_unresolved->setStyleSheet(overflowing ? QStringLiteral("QLabel { background: #c0392b; color: white; }")
                                            : QString());
    m_memory->setText(tr("%1 MB").arg(stats.bufferMegabytes, 0, 'f', 1));
}

void FrameStatsLabels::showHighlights(const HighlightSettings& highlight, const render::FrameCounts& counts)
{
    QStringList parts;
    if (highlight.collisions)
        parts << tr("collisions %1 px").arg(countText(counts.collisionPixels));
    if (highlight.coplanar)
        parts << tr("coplanar %1 px").arg(countText(counts.coplanarPixels));
    m_highlights->setText(parts.join(QStringLiteral(", ")));
    m_highlights->setVisible(!parts.isEmpty());
}

void FrameStatsLabels::clear()
{
    m_highlights->clear();
    m_highlights->setVisible(false);
    m_method->setText(QString());
    m_frameTime->setText(tr("GPU – ms"));
    m_fragments->setText(tr("– fragments"));
    m_overflow->setText(tr("overflow – px"));
    m_unresolved->setText(tr("unresolved – px"));
    m_unresolved->setStyleSheet(QString());
    m_memory->setText(tr("– MB"));
}

} // namespace trimlab::ui
