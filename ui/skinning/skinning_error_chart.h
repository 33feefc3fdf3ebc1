#pragma once
/// \file
/// E_RMS per pose as a line chart (Qt Charts): one point per pose (x = pose index, y =
/// 1000·‖A_t − A′_t‖_F / √(3n), skinning_error.h), a dot on the pose the timeline shows,
/// and, once the model was edited, the fitted model's curve in grey for comparison.

#include <QChartView>
#include <QList>
#include <QPointF>

#include <span>

class QLineSeries;
class QScatterSeries;
class QValueAxis;

namespace trimlab::ui {

class SkinningErrorChart : public QChartView {
    Q_OBJECT
public:
    explicit SkinningErrorChart(QWidget* parent = nullptr);

    /// Shows `perPose` (one value per pose; empty: no result). `fitted`: the fitted model's
    /// values when they differ from `perPose` (after an edit), or empty.
    void setErrors(std::span<const double> perPose, std::span<const double> fitted = {});
    /// Moves the marker to `pose` (hidden when out of range).
    void setCurrentPose(int pose);

    /// The curve's points (x = pose, y = E_RMS of that pose).
    [[nodiscard]] QList<QPointF> points() const;
    /// The fitted model's points (empty until an edit).
    [[nodiscard]] QList<QPointF> fittedPoints() const;
    /// The marker's pose, or −1 when none is shown.
    [[nodiscard]] int markerPose() const;

    [[nodiscard]] QSize sizeHint() const override;

private:
    void updateMarker();
    void fitAxes();

    QLineSeries* m_series = nullptr;
    QLineSeries* m_fitted = nullptr;
    QScatterSeries* m_marker = nullptr;
    QValueAxis* m_poseAxis = nullptr;
    QValueAxis* m_errorAxis = nullptr;
    int m_currentPose = 0;
};

} // namespace trimlab::ui
