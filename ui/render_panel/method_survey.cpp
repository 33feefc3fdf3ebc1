#include "ui/render_panel/method_survey.h"

#include "ui/viewport/viewport_widget.h"

#include <QTimer>

namespace trimlab::ui {

MethodSurvey::MethodSurvey(ViewportWidget* viewport, QObject* parent) : QObject(parent), m_viewport(viewport)
{
}

void MethodSurvey::start(int framesPerMethod)
{
    m_framesPerMethod = std::max(1, framesPerMethod);
    m_results.clear();
    m_next = 0;
    m_running = true;
    const int generation = ++m_generation;
    emit progress(0, int(render::fragmentMethods().size()));
    QTimer::singleShot(0, this, [this, generation] {
        if (generation == m_generation)
            measureNext();
    });
}

void MethodSurvey::cancel()
{
    if (m_running)
        finish();
}

void MethodSurvey::measureNext()
{
    const std::vector<render::MethodInfo>& methods = render::fragmentMethods();
    if (!m_running || m_next >= methods.size() || !m_viewport) {
        finish();
        return;
    }
    MethodTiming timing;
    timing.method = methods[m_next++].kind;
    try {
        const MethodMeasurement measured = m_viewport->measureMethod(timing.method, m_framesPerMethod);
        timing.milliseconds = measured.times.medianMilliseconds();
        timing.timeSource =
            QString::fromLatin1(measured.times.source().data(), qsizetype(measured.times.source().size()));
        timing.geometryPasses = measured.lastStats.methodStats.geometryPasses;
        timing.megabytes = measured.lastStats.bufferMegabytes;
        timing.fragmentsLost = measured.lastStats.counts.fragmentsLost;
    } catch (const std::exception& e) {
        timing.failure = QString::fromUtf8(e.what());
    }
    m_results.push_back(timing);
    emit progress(int(m_results.size()), int(methods.size()));
    const int generation = m_generation;
    QTimer::singleShot(0, this, [this, generation] {
        if (generation == m_generation)
            measureNext();
    });
}

void MethodSurvey::finish()
{
    m_running = false;
    ++m_generation;
    emit finished();
}

} // namespace trimlab::ui
