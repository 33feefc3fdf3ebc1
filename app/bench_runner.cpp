#include "app/bench_runner.h"

#include "app/bench_views.h"
#include "app/cli_messages.h"

#include "render/gl/gl_error.h"
#include "render/trim_renderer.h"
#include "core/trim/reference_renderer.h"

#include <QElapsedTimer>

#include <algorithm>

namespace trimlab::app {

struct BenchRunner::ViewReference {
    Camera camera;
    TrimImage trim;
    ReferenceDiagnostics diagnostics;
};

namespace {

void addFrame(BenchCell& cell, const render::FrameStats& stats)
{
    cell.geometryPasses = std::max(cell.geometryPasses, stats.methodStats.geometryPasses);
    cell.fullscreenPasses = std::max(cell.fullscreenPasses, stats.methodStats.fullscreenPasses);
    cell.megabytes = std::max(cell.megabytes, stats.bufferMegabytes);
    cell.interlock = stats.methodStats.interlock;
    cell.usesLock = stats.methodStats.usesLock;
    cell.fragmentsInSpan += stats.counts.fragmentsInSpan;
    cell.fragmentsStored += stats.counts.fragmentsStored;
    cell.fragmentsLost += stats.counts.fragmentsLost;
    cell.overflowPixels += stats.counts.overflowPixels;
    cell.unresolvedPixels += stats.counts.unresolvedPixels;
    cell.spinGiveUps += stats.counts.spinGiveUps;
}

/// A method that never holds all of a pixel's fragments at once cannot walk them for CSG,
/// highlighting or transparency (render/trim_renderer.h); the bench says so and goes on.
BenchCell notApplicableCell(render::FragmentMethodKind method, const BenchScene& scene, QSize size)
{
    BenchCell cell;
    cell.scene = QString::fromStdString(scene.name);
    cell.size = size;
    cell.method = method;
    cell.notApplicable = true;
    cell.error = QStringLiteral("holds too few of a pixel's fragments at once for CSG, highlighting or transparency");
    return cell;
}

QString sizeText(QSize size)
{
    return QStringLiteral("%1x%2").arg(size.width()).arg(size.height());
}

} // namespace

BenchRunner::BenchRunner(render::TrimRenderer& renderer, const BenchOptions& options)
    : m_renderer(renderer), m_options(options)
{
}

void BenchRunner::measureScene(const BenchScene& scene, BenchReport& report)
{
    m_renderer.setScene(scene.loaded.scene);
    const ReferenceRenderer reference(scene.loaded.scene);
    for (const QSize size : m_options.sizes) {
        QElapsedTimer clock;
        clock.start();
        const std::vector<ViewReference> views = referenceViews(reference, scene, size);
        printNote(
            QStringLiteral("%1 (%L2 triangles, %3 objects) at %4: %5 views, CPU reference %6 s; measuring %7 methods")
                .arg(QString::fromStdString(scene.name))
                .arg(qulonglong(scene.loaded.scene.triangleCount()))
                .arg(scene.loaded.scene.objects.size())
                .arg(sizeText(size))
                .arg(views.size())
                .arg(double(clock.elapsed()) / 1000.0, 0, 'f', 1)
                .arg(m_options.methods.size()));
        for (const render::FragmentMethodKind method : m_options.methods) {
            if (render::needsInspectionMethod(scene.settings) && !render::methodInfo(method).inspection) {
                report.cells.push_back(notApplicableCell(method, scene, size));
                continue;
            }
            render::MethodParameters parameters = m_options.parameters;
            report.cells.push_back(measureMethod(method, parameters, scene, size, reference, views));
            // Interlock against the spin-lock (thesis 5.2.2) on the same frames, where the
            // driver offers the choice.
            if (m_options.locks == BenchLocks::Both && report.cells.back().interlock) {
                parameters.allowInterlock = false;
                report.cells.push_back(measureMethod(method, parameters, scene, size, reference, views));
            }
        }
    }
}

std::vector<BenchRunner::ViewReference> BenchRunner::referenceViews(const ReferenceRenderer& reference,
                                                                    const BenchScene& scene, QSize size) const
{
    std::vector<ViewReference> views;
    const double aspect = double(size.width()) / double(size.height());
    for (const Camera& camera : benchViews(scene.loaded.scene.worldBounds(), aspect, m_options.views)) {
        ReferenceResult result =
            reference.render(camera, size.width(), size.height(), scene.settings, m_options.threads);
        views.push_back({camera, std::move(result.trim), std::move(result.diagnostics)});
    }
    return views;
}

BenchCell BenchRunner::measureMethod(render::FragmentMethodKind method, const render::MethodParameters& parameters,
                                     const BenchScene& scene, QSize size, const ReferenceRenderer& reference,
                                     const std::vector<ViewReference>& views)
{
    BenchCell cell;
    cell.scene = QString::fromStdString(scene.name);
    cell.size = size;
    cell.method = method;
    try {
        m_renderer.setMethod(method);
        m_renderer.setParameters(parameters);
        if (!views.empty()) // warm-up: shader build and storage allocation are not timed
            m_renderer.render(views.front().camera, scene.settings, size.width(), size.height());
        for (std::size_t i = 0; i < views.size(); ++i)
            measureView(cell, scene, reference, views[i], int(i));
    } catch (const render::GpuMemoryError& e) {
        cell.error = QString::fromUtf8(e.what());
        cell.outOfMemory = true;
    } catch (const std::exception& e) {
        cell.error = QString::fromUtf8(e.what());
    }
    return cell;
}

void BenchRunner::measureView(BenchCell& cell, const BenchScene& scene, const ReferenceRenderer& reference,
                              const ViewReference& view, int index)
{
    const QSize size = cell.size;
    for (int frame = 0; frame < m_options.repeat; ++frame) {
        m_renderer.render(view.camera, scene.settings, size.width(), size.height());
        cell.times.add(m_renderer.lastStats());
    }
    const render::FrameStats& stats = m_renderer.lastStats();
    addFrame(cell, stats);
    ++cell.views;
    const TrimAgreement agreement =
        measureTrimAgreement(m_renderer.readTrimImage(), view.trim, view.diagnostics, {},
                             referenceTieCheck(reference, view.camera, size.width(), size.height(), scene.settings));
    cell.agreement.add(agreement);
    cell.worstViewAgreement = std::min(cell.worstViewAgreement, agreement.agreement());
    const bool bounded = render::methodInfo(cell.method).bounded;
    const auto violation = agreementViolation(agreement, {}, bounded, stats.counts.fragmentsLost);
    if (violation && cell.violation.isEmpty())
        cell.violation = QStringLiteral("view %1: %2 (%3)")
                             .arg(index)
                             .arg(QString::fromStdString(*violation), QString::fromStdString(agreement.summary()));
    cell.pipelinedMs.push_back(pipelinedPeriod(scene, size, view.camera));
}

// The view's frames as the viewport issues them: back to back, each one's results read a
// frame or more later (the renderer waits only when the GPU is a whole ring of frames
// behind), so the period is the larger of the CPU's and the GPU's time per frame.
double BenchRunner::pipelinedPeriod(const BenchScene& scene, QSize size, const Camera& camera)
{
    m_renderer.setPipelined(true);
    QElapsedTimer clock;
    clock.start();
    try {
        for (int frame = 0; frame < m_options.repeat; ++frame)
            m_renderer.render(camera, scene.settings, size.width(), size.height());
        m_renderer.finishFrames();
    } catch (...) {
        m_renderer.setPipelined(false);
        throw;
    }
    const double period = double(clock.nsecsElapsed()) * 1e-6 / double(std::max(1, m_options.repeat));
    m_renderer.setPipelined(false);
    return period;
}

} // namespace trimlab::app
