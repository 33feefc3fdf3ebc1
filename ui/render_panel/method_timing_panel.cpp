#include "ui/render_panel/method_timing_panel.h"

#include "ui/render_panel/method_group.h"
#include "ui/render_panel/method_survey.h"
#include "ui/render_panel/method_timing_chart.h"
#include "ui/viewport/viewport_widget.h"

#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>

namespace trimlab::ui {

namespace {

QString barToolTip(const MethodTiming& timing, int frames)
{
    if (!timing.milliseconds)
        return MethodTimingPanel::tr("Failed: %1").arg(timing.failure);
    QString text = MethodTimingPanel::tr("%1 median of %2 frames; %3 geometry passes; %4 MB")
                       .arg(timing.timeSource)
                       .arg(frames)
                       .arg(timing.geometryPasses)
                       .arg(timing.megabytes, 0, 'f', 1);
    if (timing.fragmentsLost > 0)
        text += MethodTimingPanel::tr("; lost %1 fragments (overflow)").arg(timing.fragmentsLost);
    return text;
}

} // namespace

MethodTimingPanel::MethodTimingPanel(ViewportWidget* viewport, QWidget* parent)
    : QWidget(parent), m_viewport(viewport), m_survey(new MethodSurvey(viewport, this))
{
    setObjectName(QStringLiteral("methodTimingPanel"));
    auto* layout = new QVBoxLayout(this);
    m_measure = new QPushButton(tr("Measure all methods"), this);
    m_measure->setObjectName(QStringLiteral("measureAllButton"));
    m_measure->setToolTip(tr("Renders the current view with every method a few times (off-screen) and compares "
                             "their time per frame"));
    m_progress = new QProgressBar(this);
    m_progress->setObjectName(QStringLiteral("measureProgress"));
    m_progress->setVisible(false);
    m_note = new QLabel(tr("Time per frame of each method on the current view."), this);
    m_note->setObjectName(QStringLiteral("measureNoteLabel"));
    m_note->setWordWrap(true);
    m_chart = new MethodTimingChart(this);
    layout->addWidget(m_measure);
    layout->addWidget(m_progress);
    layout->addWidget(m_note);
    layout->addWidget(m_chart);
    connect(m_measure, &QPushButton::clicked, this, &MethodTimingPanel::toggleSurvey);
    connect(m_survey, &MethodSurvey::progress, this, &MethodTimingPanel::showProgress);
    connect(m_survey, &MethodSurvey::finished, this, &MethodTimingPanel::showResults);
}

void MethodTimingPanel::toggleSurvey()
{
    if (m_survey->isRunning()) {
        m_survey->cancel();
        return;
    }
    m_measure->setText(tr("Cancel"));
    m_progress->setVisible(true);
    m_survey->start(m_framesPerMethod);
}

void MethodTimingPanel::showProgress(int done, int total)
{
    m_progress->setRange(0, total);
    m_progress->setValue(done);
}

void MethodTimingPanel::showResults()
{
    m_measure->setText(tr("Measure all methods"));
    m_progress->setVisible(false);
    std::vector<MethodTimingChart::Bar> bars;
    const std::vector<MethodTiming>& results = m_survey->results();
    for (const render::MethodInfo& info : render::fragmentMethods()) {
        const auto measured = std::find_if(results.begin(), results.end(),
                                           [&](const MethodTiming& timing) { return timing.method == info.kind; });
        const QString toolTip = measured == results.end() ? tr("Not measured: the survey was canceled.")
                                                          : barToolTip(*measured, m_framesPerMethod);
        const std::optional<double> ms = measured == results.end() ? std::nullopt : measured->milliseconds;
        bars.push_back({methodDisplayName(info), ms, toolTip, info.kind == m_viewport->method()});
    }
    m_chart->setBars(std::move(bars));
    const QSize size = m_viewport->framePixelSize();
    m_note->setText(tr("Time per frame on the view as it was measured (%1×%2 px, %3 frames per method); the "
                       "highlighted bar is the method in use.")
                        .arg(size.width())
                        .arg(size.height())
                        .arg(m_framesPerMethod));
}

} // namespace trimlab::ui
