#include "ui/viewport/cpu_still_render.h"

#include "ui/common/background_task.h"
#include "render/rgba_qimage.h"

#include "core/trim/reference_renderer.h"

#include <QElapsedTimer>

namespace trimlab::ui {

bool CpuStillRender::Request::sameView(const Request& other) const
{
    return scene == other.scene && camera == other.camera && settings == other.settings && size == other.size;
}

CpuStillRender::CpuStillRender(QObject* parent)
    : QObject(parent),
      m_task(new BackgroundTask(this)),
      m_result(std::make_shared<QImage>()),
      m_builtReference(std::make_shared<std::shared_ptr<const ReferenceRenderer>>()),
      m_resultMs(std::make_shared<double>(0.0))
{
    connect(m_task, &BackgroundTask::succeeded, this, [this] {
        m_image = *m_result;
        m_shown = m_running;
        m_lastMs = *m_resultMs;
        emit ready();
    });
    connect(m_task, &BackgroundTask::failed, this, [this](const QString& message) {
        m_referenceScene.reset(); // build again next time
        emit failed(message);
    });
    connect(m_task, &BackgroundTask::finished, this, &CpuStillRender::onFinished);
}

CpuStillRender::~CpuStillRender() = default;

void CpuStillRender::request(const Request& request)
{
    if (!request.scene || request.size.isEmpty())
        return;
    if (m_running && m_task->isRunning()) {
        if (!m_running->sameView(request))
            m_waiting = request;
        return;
    }
    if (m_shown && m_shown->sameView(request))
        return;
    start(request);
}

void CpuStillRender::start(const Request& request)
{
    m_running = request;
    m_waiting.reset();
    if (m_referenceScene != request.scene) {
        m_referenceScene = request.scene;
        m_builtReference->reset(); // the job builds the BVH of the new scene
    }
    auto result = m_result;
    auto built = m_builtReference;
    auto milliseconds = m_resultMs;
    m_task->start([request, result, built, milliseconds](const TaskControl&) {
        QElapsedTimer timer;
        timer.start();
        if (!*built)
            *built = std::make_shared<const ReferenceRenderer>(*request.scene);
        const ReferenceResult rendered =
            (*built)->render(request.camera, request.size.width(), request.size.height(), request.settings);
        *result = render::toQImage(rendered.color);
        *milliseconds = double(timer.nsecsElapsed()) * 1e-6;
    });
}

void CpuStillRender::onFinished()
{
    m_running.reset();
    if (m_waiting) {
        const Request next = *m_waiting;
        m_waiting.reset();
        request(next);
    }
}

} // namespace trimlab::ui
