#include "ui/common/heat_map_legend.h"

#include "core/image/heat_map_colors.h"

#include <QLinearGradient>
#include <QPainter>

namespace trimlab::ui {

namespace {

constexpr int kMargin = 4;
constexpr int kBarHeight = 12;
constexpr int kGradientStops = 16;

QColor toQColor(const glm::vec3& rgb)
{
    return QColor::fromRgbF(rgb.r, rgb.g, rgb.b);
}

} // namespace

HeatMapLegend::HeatMapLegend(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("heatMapLegend"));
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
}

void HeatMapLegend::setRange(double maxValue, const QString& unit)
{
    m_max = maxValue;
    m_unit = unit;
    setToolTip(tr("Per-vertex RMS distance over all poses between the original and the approximation: "
                  "blue 0, red %1")
                   .arg(maxText()));
    update();
}

QString HeatMapLegend::maxText() const
{
    return QStringLiteral("%1 %2").arg(m_max, 0, 'g', 3).arg(m_unit);
}

QSize HeatMapLegend::sizeHint() const
{
    return {240, minimumSizeHint().height()};
}

QSize HeatMapLegend::minimumSizeHint() const
{
    return {120, 3 * kMargin + kBarHeight + fontMetrics().height()};
}

void HeatMapLegend::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    const QRect bar(kMargin, kMargin, width() - 2 * kMargin, kBarHeight);
    QLinearGradient gradient(bar.topLeft(), bar.topRight());
    for (int i = 0; i <= kGradientStops; ++i) {
        const double t = double(i) / kGradientStops;
        gradient.setColorAt(t, toQColor(heatMapColor(t)));
    }
    painter.fillRect(bar, gradient);
    painter.setPen(palette().color(QPalette::WindowText));
    painter.drawRect(bar.adjusted(0, 0, -1, -1));
    const QRect text(kMargin, bar.bottom() + kMargin, bar.width(), fontMetrics().height());
    painter.drawText(text, Qt::AlignLeft | Qt::AlignVCenter, QStringLiteral("0"));
    painter.drawText(text, Qt::AlignRight | Qt::AlignVCenter, maxText());
}

} // namespace trimlab::ui
