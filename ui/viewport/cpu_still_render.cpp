#include "ui/viewport/cpu_still_render.h"

#include "ui/common/background_job.h"
#include "render/rgba_qimage.h"

#include "core/trim/reference_renderer.h"

#include <QElapsedTimer>

namespace trimlab::ui {

bool CpuStillRender::Request::sameView(const Request& other) const
{
    return scene == other.scene && camera == other.camera && settings == other.settings && size == other.size;
}

CpuStillRender::CpuStillRender(QObject* parent) : QObject(parent), m_job(new BackgroundJob<Rendered>(this))
{
    connect(m_job, &BackgroundJobBase::succeeded, this, [this] {
        Rendered rendered = m_job->takeResult();
        if (m_referenceScene == m_running->scene)
            m_builtReference = std::move(rendered.reference);
        m_image = std::move(rendered.image);
        m_shown = m_running;
        m_lastMs = rendered.milliseconds;
        emit ready();
    });
    connect(m_job, &BackgroundJobBase::failed, this, [this](const QString& message) {
        m_referenceScene.reset(); // build again next time
        m_builtReference.reset();
        emit failed(message);
    });
    connect(m_job, &BackgroundJobBase::finished, this, &CpuStillRender::onFinished);
}

CpuStillRender::~CpuStillRender() = default;

void CpuStillRender::request(const Request& request)
{
    if (!request.scene || request.size.isEmpty())
        return;
    if (m_running && m_job->isRunning()) {
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
        m_builtReference.reset(); // the job builds the BVH of the new scene
    }
    m_job->start([request, built = m_builtReference](const TaskControl&) {
        QElapsedTimer timer;
        timer.start();
        Rendered rendered;
        rendered.reference = built ? built : std::make_shared<const ReferenceRenderer>(*request.scene);
        const ReferenceResult result =
            rendered.reference->render(request.camera, request.size.width(), request.size.height(), request.settings);
        rendered.image = render::toQImage(result.color);
        rendered.milliseconds = double(timer.nsecsElapsed()) * 1e-6;
        return rendered;
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
