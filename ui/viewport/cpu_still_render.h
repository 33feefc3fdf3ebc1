#pragma once
/// \file
/// The last resort of the view when no GPU method can render a frame (every memory
/// fallback failed, render/memory_fallback.h): the exact CPU reference
/// (core/trim/reference_renderer.h) renders a still image off the UI thread. A request
/// made while one renders replaces any waiting one, so only the newest view is rendered
/// next; the BVH is built once per scene.

#include "core/scene/scene.h"
#include "core/trim/trim_settings.h"
#include "core/view/camera.h"

#include <QImage>
#include <QObject>
#include <QSize>

#include <memory>
#include <optional>

namespace trimlab {
class ReferenceRenderer;
}

namespace trimlab::ui {

class BackgroundJobBase;
template <class T>
class BackgroundJob;

class CpuStillRender : public QObject {
    Q_OBJECT
public:
    /// What to render. The scene is shared (not copied) and must not change while shared.
    struct Request {
        std::shared_ptr<const Scene> scene;
        Camera camera;
        TrimSettings settings;
        QSize size;
        /// Equal requests render equal images (same scene object, view and settings).
        [[nodiscard]] bool sameView(const Request& other) const;
    };

    explicit CpuStillRender(QObject* parent = nullptr);
    ~CpuStillRender() override;

    /// Renders `request` unless it is the shown or the pending one.
    void request(const Request& request);
    /// The newest finished image and the request it answers (nullopt before the first).
    [[nodiscard]] const QImage& image() const { return m_image; }
    [[nodiscard]] const std::optional<Request>& shown() const { return m_shown; }
    /// Milliseconds the last image took (BVH build included when the scene was new).
    [[nodiscard]] double lastMilliseconds() const { return m_lastMs; }

signals:
    /// A new image is ready (image(), shown()).
    void ready();
    /// The reference failed (e.g. out of memory); `message` says why.
    void failed(const QString& message);

private:
    /// What one job renders: the image, its time, and the reference it used (built for a
    /// new scene, else the one it was given).
    struct Rendered {
        QImage image;
        double milliseconds = 0.0;
        std::shared_ptr<const ReferenceRenderer> reference;
    };

    void start(const Request& request);
    void onFinished();

    BackgroundJob<Rendered>* m_job;
    std::optional<Request> m_running;
    std::optional<Request> m_waiting;
    std::optional<Request> m_shown;
    std::shared_ptr<const Scene> m_referenceScene; ///< the scene m_builtReference was built for
    std::shared_ptr<const ReferenceRenderer> m_builtReference;
    QImage m_image;
    double m_lastMs = 0.0;
};

} // namespace trimlab::ui
