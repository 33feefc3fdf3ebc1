#pragma once
/// \file
/// The "Frame statistics" dock's lower part: the "Measure all methods" button, a progress
/// bar while the survey runs (method_survey.h; the button then cancels), and the bar
/// chart of time per frame per method for the current view (method_timing_chart.h).

#include <QWidget>

class QLabel;
class QProgressBar;
class QPushButton;

namespace trimlab::ui {

class MethodSurvey;
class MethodTimingChart;
class ViewportWidget;

class MethodTimingPanel : public QWidget {
    Q_OBJECT
public:
    /// Measures `viewport`'s current view.
    explicit MethodTimingPanel(ViewportWidget* viewport, QWidget* parent = nullptr);

    /// Timed frames per method (default 3).
    void setFramesPerMethod(int frames) { m_framesPerMethod = frames; }
    [[nodiscard]] MethodSurvey* survey() const { return m_survey; }
    [[nodiscard]] MethodTimingChart* chart() const { return m_chart; }

private:
    void toggleSurvey();
    void showProgress(int done, int total);
    void showResults();

    ViewportWidget* m_viewport;
    MethodSurvey* m_survey;
    QPushButton* m_measure = nullptr;
    QProgressBar* m_progress = nullptr;
    QLabel* m_note = nullptr;
    MethodTimingChart* m_chart = nullptr;
    int m_framesPerMethod = 3;
};

} // namespace trimlab::ui
