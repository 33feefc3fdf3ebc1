#include "ui/render_panel/method_timing_chart.h"

#include <QHelpEvent>
#include <QPainter>
#include <QToolTip>

#include <algorithm>

namespace trimlab::ui {

namespace {

constexpr int kRowHeight = 22;
constexpr int kMargin = 6;
constexpr int kValueWidth = 70;

QString valueText(const MethodTimingChart::Bar& bar)
{
    return bar.milliseconds ? MethodTimingChart::tr("%1 ms").arg(*bar.milliseconds, 0, 'f', 2)
                            : MethodTimingChart::tr("n/a");
}

} // namespace

MethodTimingChart::MethodTimingChart(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("methodTimingChart"));
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
}

void MethodTimingChart::setBars(std::vector<Bar> bars)
{
    m_bars = std::move(bars);
    updateGeometry();
    update();
}

QSize MethodTimingChart::sizeHint() const
{
    return {320, 2 * kMargin + std::max<int>(1, int(m_bars.size())) * kRowHeight};
}

QSize MethodTimingChart::minimumSizeHint() const
{
    return {200, sizeHint().height()};
}

int MethodTimingChart::labelWidth() const
{
    int widest = 0;
    for (const Bar& bar : m_bars)
        widest = std::max(widest, fontMetrics().horizontalAdvance(bar.label));
    return std::min(widest + kMargin, width() / 2);
}

QRect MethodTimingChart::rowRect(int index) const
{
    return {kMargin, kMargin + index * kRowHeight, width() - 2 * kMargin, kRowHeight};
}

int MethodTimingChart::rowAt(QPoint position) const
{
    for (int i = 0; i < int(m_bars.size()); ++i)
        if (rowRect(i).contains(position))
            return i;
    return -1;
}

void MethodTimingChart::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    if (m_bars.empty()) {
        painter.setPen(palette().color(QPalette::PlaceholderText));
        painter.drawText(rect(), Qt::AlignCenter, tr("Not measured yet"));
        return;
    }
    double longest = 0.0;
    for (const Bar& bar : m_bars)
        longest = std::max(longest, bar.milliseconds.value_or(0.0));
    const int labels = labelWidth();
    for (int i = 0; i < int(m_bars.size()); ++i) {
        const Bar& bar = m_bars[std::size_t(i)];
        const QRect row = rowRect(i);
        painter.setPen(palette().color(QPalette::WindowText));
        painter.drawText(QRect(row.left(), row.top(), labels, row.height()), Qt::AlignVCenter | Qt::AlignLeft,
                         bar.label);
        const int track = std::max(1, row.width() - labels - kValueWidth);
        const QRect area(row.left() + labels, row.top() + 4, track, row.height() - 8);
        const double fraction = bar.milliseconds && longest > 0.0 ? *bar.milliseconds / longest : 1.0;
        const QRect filled(area.topLeft(), QSize(std::max(2, int(fraction * area.width())), area.height()));
        if (bar.milliseconds)
            painter.fillRect(filled, bar.highlighted ? QColor(230, 126, 34) : QColor(52, 152, 219));
        else
            painter.fillRect(filled, QBrush(QColor(150, 150, 150), Qt::BDiagPattern));
        painter.drawText(QRect(filled.right() + 4, row.top(), kValueWidth, row.height()),
                         Qt::AlignVCenter | Qt::AlignLeft, valueText(bar));
    }
}

bool MethodTimingChart::event(QEvent* event)
{
    if (event->type() != QEvent::ToolTip)
        return QWidget::event(event);
    auto* help = static_cast<QHelpEvent*>(event);
    const int row = rowAt(help->pos());
    if (row < 0 || m_bars[std::size_t(row)].toolTip.isEmpty()) {
        QToolTip::hideText();
        event->ignore();
        return true;
    }
    QToolTip::showText(help->globalPos(), m_bars[std::size_t(row)].toolTip, this, rowRect(row));
    return true;
}

} // namespace trimlab::ui
