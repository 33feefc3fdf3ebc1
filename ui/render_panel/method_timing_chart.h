#pragma once
/// \file
/// A horizontal bar chart of time per frame, one bar per method, drawn with QPainter (no
/// chart library): the label on the left, a bar proportional to the time, the value at
/// its end. A method without a time shows a hatched "n/a" bar whose tooltip is the reason.

#include <QString>
#include <QWidget>

#include <optional>
#include <vector>

namespace trimlab::ui {

class MethodTimingChart : public QWidget {
    Q_OBJECT
public:
    struct Bar {
        QString label;
        std::optional<double> milliseconds; ///< nullopt: n/a
        QString toolTip;                    ///< the reason for n/a, or details
        bool highlighted = false;           ///< e.g. the method the view uses
    };

    explicit MethodTimingChart(QWidget* parent = nullptr);

    void setBars(std::vector<Bar> bars);
    [[nodiscard]] const std::vector<Bar>& bars() const { return m_bars; }
    /// The bar's row rectangle (label and bar), in widget coordinates.
    [[nodiscard]] QRect rowRect(int index) const;

    [[nodiscard]] QSize sizeHint() const override;
    [[nodiscard]] QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;
    bool event(QEvent* event) override;

private:
    [[nodiscard]] int labelWidth() const;
    [[nodiscard]] int rowAt(QPoint position) const;

    std::vector<Bar> m_bars;
};

} // namespace trimlab::ui
