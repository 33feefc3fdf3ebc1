#pragma once
/// \file
/// The legend of the error heat map: the color ramp of heat_map_colors.h as a horizontal
/// bar, labeled with 0 at the left end and the largest value (with its unit) at the right.

#include <QString>
#include <QWidget>

namespace trimlab::ui {

class HeatMapLegend : public QWidget {
    Q_OBJECT
public:
    explicit HeatMapLegend(QWidget* parent = nullptr);

    /// The value of the red end and the unit named after it (e.g. "length units").
    void setRange(double maxValue, const QString& unit);
    [[nodiscard]] double maxValue() const { return m_max; }
    /// The right-hand label as drawn.
    [[nodiscard]] QString maxText() const;

    [[nodiscard]] QSize sizeHint() const override;
    [[nodiscard]] QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    double m_max = 0.0;
    QString m_unit;
};

} // namespace trimlab::ui
