#include "render_verb.h"

#include "cli_messages.h"
#include "render_options.h"
#include "trim_exports.h"

#include "gl/gl_error.h"
#include "gl/offscreen_gl_context.h"
#include "scene/scene_source.h"
#include "trim/reference_renderer.h"
#include "trim_renderer.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QGuiApplication>

#include <algorithm>
#include <cstdlib>
#include <vector>
#include <memory>

namespace trimlab::app {

namespace {

struct RenderOutcome {
    QImage color;
    TrimImage trim;
    QString statistics;
};

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[values.size() / 2];
}

// GPU times the driver flagged as implausible (negative) are left out of the median.
QString timingText(std::vector<double> gpuMs, const std::vector<double>& wallMs)
{
    std::erase_if(gpuMs, [](double v) { return v < 0.0; });
    const QString frames = wallMs.size() == 1 ? QStringLiteral("1 frame") : QStringLiteral("median of %1 frames").arg(wallMs.size());
    return QStringLiteral("%1 ms GPU, %2 ms wall (%3)")
        .arg(gpuMs.empty() ? QStringLiteral("n/a") : QString::number(median(gpuMs), 'f', 2))
        .arg(median(wallMs), 0, 'f', 2)
        .arg(frames);
}

RenderOutcome renderWithKPlus(const LoadedScene& loaded, const RenderOptions& options, const Camera& camera)
{
    render::OffscreenGlContext gl;
    render::TrimRenderer renderer(gl.context());
    renderer.setScene(loaded.scene);
    renderer.setK(options.k);
    std::vector<double> gpuMs;
    std::vector<double> wallMs;
    for (int i = 0; i < options.repeat; ++i) {
        renderer.render(camera, options.trim, options.width, options.height);
        gpuMs.push_back(renderer.lastStats().gpuMilliseconds);
        wallMs.push_back(renderer.lastStats().wallMilliseconds);
    }
    RenderOutcome outcome{renderer.readColor(), renderer.readTrimImage(), {}};
    const render::FrameStats& s = renderer.lastStats();
    outcome.statistics = QStringLiteral("k+-buffer (k = %1) on %2: %3, %4 fragments, %5 overflowed pixels "
                                        "(%6 unresolved), %7 MB")
                             .arg(s.k)
                             .arg(gl.capabilities().renderer, timingText(gpuMs, wallMs))
                             .arg(s.counts.fragmentsInSpan)
                             .arg(s.counts.overflowPixels)
                             .arg(s.counts.unresolvedPixels)
                             .arg(s.bufferMegabytes, 0, 'f', 1);
    if (s.counts.spinGiveUps > 0)
        outcome.statistics += QStringLiteral(", %1 fragments gave up on the spin-lock").arg(s.counts.spinGiveUps);
    return outcome;
}

QImage toQImage(const RgbaImage& image)
{
    QImage result(image.width, image.height, QImage::Format_RGBA8888);
    for (int y = 0; y < image.height; ++y)
        std::copy_n(&image.rgba[std::size_t(y) * image.width * 4], image.width * 4, result.scanLine(y));
    return result;
}

RenderOutcome renderWithReference(const LoadedScene& loaded, const RenderOptions& options, const Camera& camera)
{
    QElapsedTimer wall;
    wall.start();
    const ReferenceRenderer reference(loaded.scene);
    const double buildMs = double(wall.nsecsElapsed()) * 1e-6;
    std::vector<double> renderMs;
    ReferenceResult result;
    for (int i = 0; i < options.repeat; ++i) {
        result = reference.render(camera, options.width, options.height, options.trim, options.threads);
        renderMs.push_back(result.stats.wallMs);
    }
    RenderOutcome outcome{toQImage(result.color), std::move(result.trim), {}};
    outcome.statistics = QStringLiteral("reference ray caster: %1 ms wall (%2) on %3 threads (+ %4 ms BVH build), "
                                        "%5 hits, at most %6 per pixel")
                             .arg(median(renderMs), 0, 'f', 2)
                             .arg(renderMs.size() == 1 ? QStringLiteral("1 frame")
                                                       : QStringLiteral("median of %1 frames").arg(renderMs.size()))
                             .arg(result.stats.threads)
                             .arg(buildMs, 0, 'f', 2)
                             .arg(result.stats.totalHits)
                             .arg(result.stats.maxHitsPerPixel);
    return outcome;
}

// Trimming needs a closed oriented surface. Asked for explicitly, that is an error; by
// default the verb renders untrimmed and says why.
bool resolveTrimAvailability(const LoadedScene& loaded, RenderOptions& options)
{
    if (!options.trim.trimEnabled || loaded.trimmable())
        return true;
    const QString reason = QString::fromStdString(loaded.trimUnavailableReason());
    if (options.ruleGiven) {
        printError(QStringLiteral("--rule %1 is unavailable for %2: %3")
                       .arg(QString::fromLatin1(ruleName(options.trim.rule).data()),
                            QString::fromStdString(loaded.displayName), reason));
        return false;
    }
    printNote(QStringLiteral("rendering without trimming: %1").arg(reason));
    options.trim.trimEnabled = false;
    return true;
}

Camera chooseCamera(const LoadedScene& loaded, const RenderOptions& options)
{
    const Bounds bounds = loaded.scene.worldBounds();
    if (options.camera)
        return withDepthRange(*options.camera, bounds);
    return fitCamera(bounds, double(options.width) / double(options.height));
}

void writeOutputs(const RenderOutcome& outcome, const RenderOptions& options, const Camera& camera)
{
    saveImage(outcome.color, options.output);
    if (!options.depthOutput.isEmpty())
        writePfm(options.depthOutput.toStdString(), rayDistanceImage(outcome.trim, camera));
    if (!options.idsOutput.isEmpty())
        saveImage(idImage(outcome.trim), options.idsOutput);
}

int renderLoaded(RenderOptions options)
{
    const LoadedScene loaded = loadScene(options.source);
    if (!resolveTrimAvailability(loaded, options))
        return 1;
    const Camera camera = chooseCamera(loaded, options);
    const RenderOutcome outcome = options.backend == Backend::KPlus ? renderWithKPlus(loaded, options, camera)
                                                                     : renderWithReference(loaded, options, camera);
    writeOutputs(outcome, options, camera);
    printLine(QStringLiteral("%1: %2x%3, %4, %5 -> %6")
                  .arg(QString::fromStdString(loaded.displayName))
                  .arg(options.width)
                  .arg(options.height)
                  .arg(options.trim.trimEnabled ? QString::fromLatin1(ruleName(options.trim.rule).data())
                                                : QStringLiteral("no trimming"))
                  .arg(outcome.statistics, options.output));
    printLine(QStringLiteral("camera: %1").arg(QString::fromStdString(formatCamera(camera))));
    return 0;
}

bool hasDisplay()
{
    const char* platform = std::getenv("QT_QPA_PLATFORM");
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (platform && *platform) || (display && *display) || (wayland && *wayland);
}

} // namespace

int runRenderVerb(int argc, char** argv, const QStringList& arguments)
{
    QString help;
    auto parsed = parseRenderOptions(arguments, &help);
    if (auto* error = std::get_if<QString>(&parsed)) {
        if (!help.isEmpty()) {
            printLine(help);
            return 0;
        }
        printError(*error);
        return 2;
    }
    const RenderOptions& options = std::get<RenderOptions>(parsed);
    std::unique_ptr<QCoreApplication> application;
    if (options.backend == Backend::KPlus) {
        if (!hasDisplay()) {
            printError("the OpenGL backend needs a display; run under 'xvfb-run -a' or use --backend reference");
            return 1;
        }
        application = std::make_unique<QGuiApplication>(argc, argv);
    } else {
        application = std::make_unique<QCoreApplication>(argc, argv);
    }
    return runGuarded([&] { return renderLoaded(options); });
}

} // namespace trimlab::app
