#include "ui/design/deformation_track.h"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace trimlab::ui {

namespace {

constexpr int kMargin = 12;
constexpr int kBandTop = 4;
constexpr int kBandHeight = 22;
constexpr int kTickTop = kBandTop + kBandHeight + 4;
constexpr int kTickHeight = 8;
constexpr int kMarkSize = 6;

/// Alternating band colors, so neighbouring sets stay apart.
QColor bandColor(std::size_t set)
{
    static const QColor colors[] = {QColor(70, 110, 170), QColor(160, 110, 60)};
    return colors[set % 2];
}

QString ruleText(DynamicRule rule)
{
    const std::string_view name = dynamicRuleDisplayName(rule);
    return QString::fromUtf8(name.data(), qsizetype(name.size()));
}

} // namespace

DeformationTrack::DeformationTrack(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("deformationTrack"));
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    setToolTip(tr("Frames of the deformation history. Bands: sets of concurrent disjoint deformations with their "
                  "rule; triangles: their reference frames. Click to show a frame."));
}

void DeformationTrack::setHistory(int frameCount, std::vector<timeline::DeformationSet> sets, int shownFrame)
{
    m_frameCount = std::max(frameCount, 0);
    m_sets = std::move(sets);
    m_shownFrame = shownFrame;
    update();
}

void DeformationTrack::setShownFrame(int frame)
{
    m_shownFrame = frame;
    update();
}

QList<int> DeformationTrack::referenceFrames() const
{
    QList<int> frames;
    for (const timeline::DeformationSet& set : m_sets)
        frames << set.referenceFrame();
    return frames;
}

QStringList DeformationTrack::setLabels() const
{
    QStringList labels;
    for (std::size_t s = 0; s < m_sets.size(); ++s)
        labels << tr("Set %1: %2").arg(s + 1).arg(ruleText(m_sets[s].rule));
    return labels;
}

double DeformationTrack::frameX(int frame) const
{
    const double span = std::max(1, width() - 2 * kMargin);
    return kMargin + (m_frameCount > 1 ? span * frame / (m_frameCount - 1) : 0.0);
}

int DeformationTrack::frameAt(double x) const
{
    if (m_frameCount <= 1)
        return 0;
    const double span = std::max(1, width() - 2 * kMargin);
    return std::clamp(int(std::lround((x - kMargin) / span * (m_frameCount - 1))), 0, m_frameCount - 1);
}

QSize DeformationTrack::sizeHint() const
{
    return {400, kTickTop + kTickHeight + 4};
}

QSize DeformationTrack::minimumSizeHint() const
{
    return {120, kTickTop + kTickHeight + 4};
}

void DeformationTrack::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.fillRect(rect(), palette().base());
    if (m_frameCount == 0)
        return;
    paintSets(painter);
    paintTicks(painter);
    const double x = frameX(m_shownFrame);
    painter.setPen(QPen(palette().highlight().color(), 2.0));
    painter.drawLine(QPointF(x, 0), QPointF(x, height()));
}

// A set's band runs from its reference frame to its last frame (an empty set: a sliver
// at its reference), with its label clipped to the band.
void DeformationTrack::paintSets(QPainter& painter) const
{
    const QStringList labels = setLabels();
    for (std::size_t s = 0; s < m_sets.size(); ++s) {
        const timeline::DeformationSet& set = m_sets[s];
        const double left = frameX(set.referenceFrame());
        const double right = std::max(frameX(set.referenceFrame() + set.frameCount), left + 4.0);
        const QRectF band(left, kBandTop, right - left, kBandHeight);
        painter.setPen(Qt::NoPen);
        painter.setBrush(bandColor(s));
        painter.drawRoundedRect(band, 3, 3);
        painter.setPen(Qt::white);
        painter.drawText(band.adjusted(kMarkSize + 2, 0, -2, 0), Qt::AlignVCenter | Qt::AlignLeft,
                         painter.fontMetrics().elidedText(labels[int(s)], Qt::ElideRight, int(band.width()) - 10));
        QPainterPath mark; // the reference frame: a triangle pointing down at its tick
        mark.moveTo(left - kMarkSize, kTickTop - kMarkSize);
        mark.lineTo(left + kMarkSize, kTickTop - kMarkSize);
        mark.lineTo(left, kTickTop + kMarkSize / 2.0);
        mark.closeSubpath();
        painter.setPen(Qt::NoPen);
        painter.setBrush(QColor(230, 200, 60));
        painter.drawPath(mark);
    }
}

void DeformationTrack::paintTicks(QPainter& painter) const
{
    painter.setPen(palette().text().color());
    const int every = std::max(1, m_frameCount / std::max(1, width() / 6)); // at most one tick per 6 px
    for (int f = 0; f < m_frameCount; f += every) {
        const double x = frameX(f);
        painter.drawLine(QPointF(x, kTickTop), QPointF(x, kTickTop + kTickHeight));
    }
}

void DeformationTrack::mousePressEvent(QMouseEvent* event)
{
    if (event->button() == Qt::LeftButton && m_frameCount > 0)
        emit frameClicked(frameAt(event->position().x()));
}

void DeformationTrack::mouseMoveEvent(QMouseEvent* event)
{
    if ((event->buttons() & Qt::LeftButton) && m_frameCount > 0)
        emit frameClicked(frameAt(event->position().x()));
}

} // namespace trimlab::ui
