#include "ui/skinning/skinning_error_chart.h"

#include <QChart>
#include <QLineSeries>
#include <QScatterSeries>
#include <QValueAxis>

#include <algorithm>

namespace trimlab::ui {

namespace {

constexpr double kMarkerSize = 9.0;
constexpr double kHeadroom = 1.1; ///< the error axis ends this much above the largest value

QList<QPointF> perPosePoints(std::span<const double> values)
{
    QList<QPointF> points;
    points.reserve(qsizetype(values.size()));
    for (std::size_t pose = 0; pose < values.size(); ++pose)
        points.append(QPointF(double(pose), values[pose]));
    return points;
}

} // namespace

SkinningErrorChart::SkinningErrorChart(QWidget* parent) : QChartView(parent)
{
    setObjectName(QStringLiteral("skinningErrorChart"));
    setRenderHint(QPainter::Antialiasing);
    auto* chart = new QChart;
    chart->legend()->hide();
    chart->setMargins(QMargins(2, 2, 2, 2));
    chart->setBackgroundRoundness(0);
    m_fitted = new QLineSeries;
    m_fitted->setName(tr("Fitted"));
    m_fitted->setColor(QColor(150, 150, 150));
    m_series = new QLineSeries;
    m_series->setName(tr("E_RMS"));
    m_marker = new QScatterSeries;
    m_marker->setName(tr("Current pose"));
    m_marker->setMarkerSize(kMarkerSize);
    m_marker->setColor(QColor(220, 40, 30));
    m_marker->setBorderColor(Qt::white);
    m_poseAxis = new QValueAxis;
    m_poseAxis->setTitleText(tr("pose"));
    m_poseAxis->setLabelFormat(QStringLiteral("%d"));
    m_errorAxis = new QValueAxis;
    m_errorAxis->setTitleText(tr("E_RMS"));
    m_errorAxis->setLabelFormat(QStringLiteral("%.3g"));
    chart->addAxis(m_poseAxis, Qt::AlignBottom);
    chart->addAxis(m_errorAxis, Qt::AlignLeft);
    for (QXYSeries* series :
         {static_cast<QXYSeries*>(m_fitted), static_cast<QXYSeries*>(m_series), static_cast<QXYSeries*>(m_marker)}) {
        chart->addSeries(series);
        series->attachAxis(m_poseAxis);
        series->attachAxis(m_errorAxis);
    }
    setChart(chart);
    setErrors({});
}

void SkinningErrorChart::setErrors(std::span<const double> perPose, std::span<const double> fitted)
{
    m_series->replace(perPosePoints(perPose));
    m_fitted->replace(perPosePoints(fitted));
    fitAxes();
    updateMarker();
}

void SkinningErrorChart::fitAxes()
{
    const int poses = int(m_series->count());
    m_poseAxis->setRange(0.0, double(std::max(1, poses - 1)));
    m_poseAxis->setTickCount(std::clamp(poses, 2, 6));
    double largest = 0.0;
    for (const QLineSeries* series : {m_series, m_fitted})
        for (const QPointF& point : series->points())
            largest = std::max(largest, point.y());
    m_errorAxis->setRange(0.0, largest > 0.0 ? largest * kHeadroom : 1.0);
}

void SkinningErrorChart::setCurrentPose(int pose)
{
    m_currentPose = pose;
    updateMarker();
}

void SkinningErrorChart::updateMarker()
{
    if (m_currentPose < 0 || m_currentPose >= m_series->count()) {
        m_marker->clear();
        return;
    }
    m_marker->replace(QList<QPointF>{m_series->at(m_currentPose)});
}

QList<QPointF> SkinningErrorChart::points() const
{
    return m_series->points();
}

QList<QPointF> SkinningErrorChart::fittedPoints() const
{
    return m_fitted->points();
}

int SkinningErrorChart::markerPose() const
{
    return m_marker->count() == 1 ? int(m_marker->at(0).x()) : -1;
}

QSize SkinningErrorChart::sizeHint() const
{
    return {320, 200};
}

} // namespace trimlab::ui
