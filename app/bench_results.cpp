#include "app/bench_results.h"

namespace trimlab::app {

const BenchCell* findCell(const BenchReport& report, const BenchCell& cell, render::FragmentMethodKind method)
{
    for (const BenchCell& other : report.cells)
        if (other.method == method && other.scene == cell.scene && other.size == cell.size)
            return &other;
    return nullptr;
}

const BenchCell* findInterlockCell(const BenchReport& report, const BenchCell& cell)
{
    for (const BenchCell& other : report.cells)
        if (other.method == cell.method && other.scene == cell.scene && other.size == cell.size && other.interlock)
            return &other;
    return nullptr;
}

std::optional<double> timeRatio(const BenchCell& cell, const BenchCell* base)
{
    if (!base || !cell.rendered() || !base->rendered() || cell.times.frames() == 0 || base->times.frames() == 0)
        return std::nullopt;
    const bool gpu = cell.times.gpuTimed() && base->times.gpuTimed();
    const double numerator = gpu ? cell.times.medianGpuMilliseconds() : cell.times.medianWallMilliseconds();
    const double denominator = gpu ? base->times.medianGpuMilliseconds() : base->times.medianWallMilliseconds();
    if (denominator <= 0.0)
        return std::nullopt;
    return numerator / denominator;
}

double pipelinedMilliseconds(const BenchCell& cell)
{
    return render::medianOf(cell.pipelinedMs);
}

std::optional<double> pipelinedToGpu(const BenchCell& cell)
{
    const double gpuMs = cell.times.medianGpuMilliseconds();
    if (!cell.rendered() || cell.pipelinedMs.empty() || gpuMs <= 0.0)
        return std::nullopt;
    return pipelinedMilliseconds(cell) / gpuMs;
}

QString lockId(const BenchCell& cell)
{
    if (!cell.usesLock)
        return QStringLiteral("none");
    return cell.interlock ? QStringLiteral("interlock") : QStringLiteral("spin-lock");
}

QString methodId(render::FragmentMethodKind method)
{
    const std::string_view id = render::methodInfo(method).id;
    return QString::fromLatin1(id.data(), qsizetype(id.size()));
}

} // namespace trimlab::app
