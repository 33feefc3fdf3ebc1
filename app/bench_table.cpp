#include "app/bench_table.h"

#include <array>

namespace trimlab::app {

namespace {

struct Column {
    const char* title;
    int width;
    bool left; ///< left-aligned text, else right-aligned numbers
};

constexpr std::array<Column, 19> kColumns = {{
    {"scene", 20, true},    {"size", 10, true},         {"method", 20, true},      {"lock", 9, true},
    {"ms/frame", 9, false}, {"time", 5, true},          {"pipe ms", 8, false},     {"pipe/GPU", 8, false},
    {"passes", 6, false},   {"MB", 8, false},           {"fragments", 11, false},  {"stored", 11, false},
    {"lost", 9, false},     {"overflow px", 11, false}, {"unresolved", 10, false}, {"agree %", 8, false},
    {"vs F2B", 7, false},   {"vs AB_LL", 8, false},     {"vs ilock", 8, false},
}};

QString formatRow(const QStringList& fields)
{
    QStringList padded;
    for (qsizetype i = 0; i < fields.size() && i < qsizetype(kColumns.size()); ++i) {
        const Column& column = kColumns[std::size_t(i)];
        padded << (column.left ? fields[i].leftJustified(column.width) : fields[i].rightJustified(column.width));
    }
    return padded.join(QLatin1Char(' ')).trimmed();
}

QString ratioText(const std::optional<double>& ratio)
{
    return ratio ? QString::number(*ratio, 'f', 2) : QStringLiteral("n/a");
}

QString sizeText(QSize size)
{
    return QStringLiteral("%1x%2").arg(size.width()).arg(size.height());
}

QString cellLine(const BenchReport& report, const BenchCell& cell)
{
    const QStringList identity{cell.scene, sizeText(cell.size), methodId(cell.method),
                               cell.rendered() ? lockId(cell) : QStringLiteral("-")};
    if (!cell.rendered())
        return formatRow(identity) + QStringLiteral("  %1: %2")
                                         .arg(cell.outOfMemory     ? QStringLiteral("out of GPU memory")
                                              : cell.notApplicable ? QStringLiteral("not applicable")
                                                                   : QStringLiteral("failed"),
                                              cell.error.section(QLatin1Char('\n'), 0, 0));
    const QString agreement = QString::number(100.0 * cell.agreement.agreement(), 'f', 3) +
                              (cell.violation.isEmpty() ? QString() : QStringLiteral("!"));
    return formatRow(
        identity +
        QStringList{
            QString::number(cell.times.medianMilliseconds(), 'f', 2),
            QString::fromLatin1(cell.times.source().data(), qsizetype(cell.times.source().size())),
            QString::number(pipelinedMilliseconds(cell), 'f', 2),
            ratioText(pipelinedToGpu(cell)),
            QString::number(cell.geometryPasses),
            QString::number(cell.megabytes, 'f', 1),
            QString::number(cell.fragmentsInSpan),
            QString::number(cell.fragmentsStored),
            QString::number(cell.fragmentsLost),
            QString::number(cell.overflowPixels),
            QString::number(cell.unresolvedPixels),
            agreement,
            ratioText(timeRatio(cell, findCell(report, cell, render::FragmentMethodKind::PeelingF2B))),
            ratioText(timeRatio(cell, findCell(report, cell, render::FragmentMethodKind::ABufferLinkedList))),
            cell.usesLock && !cell.interlock ? ratioText(timeRatio(cell, findInterlockCell(report, cell)))
                                             : QStringLiteral("-"),
        });
}

QString parameterText(const render::MethodParameters& parameters)
{
    return QStringLiteral("k = %1 (capacity-bounded methods), S = %2 shared counters (S-buffer family)")
        .arg(parameters.k)
        .arg(parameters.sharedCounters);
}

} // namespace

QStringList benchHeaderLines(const BenchHeader& header)
{
    QStringList sizes;
    for (const QSize size : header.sizes)
        sizes << sizeText(size);
    QStringList methods;
    for (const render::FragmentMethodKind method : header.methods)
        methods << methodId(method);
    return {
        QStringLiteral("TrimLab %1 bench, %2").arg(header.version, header.date),
        QStringLiteral("OpenGL: %1").arg(header.openGl),
        QStringLiteral("CPU threads: %1").arg(header.cpuThreads),
        QStringLiteral("sizes: %1; %2 views on an orbit per scene; %3 timed frames per view after one warm-up frame")
            .arg(sizes.join(QStringLiteral(", ")))
            .arg(header.views)
            .arg(header.repeat),
        QStringLiteral("parameters: %1").arg(parameterText(header.parameters)),
        QStringLiteral("methods: %1").arg(methods.join(QStringLiteral(", "))),
        QStringLiteral("ms/frame: median over all timed frames of all views; time: GPU = GL_TIME_ELAPSED (every "
                       "frame had one), wall = the render call including the wait for the GPU"),
        QStringLiteral("pipe ms: the same frames pipelined as the viewport renders them (issued back to back, results "
                       "read a frame or more later), wall time / frames, median over the views; pipe/GPU: that "
                       "period / the median GPU time (near 1: the CPU's work overlaps the GPU's)"),
        QStringLiteral("passes: geometry passes, most over the views; MB: method + render target + scene, most over "
                       "the views"),
        QStringLiteral("fragments (in the kept span), stored, lost, overflow px, unresolved: last frame of each view, "
                       "summed over the views"),
        QStringLiteral("agree %: pixels agreeing with the CPU reference over all views (criteria of the render "
                       "tests per view: >= 99.9 %, <= 5 % excluded; '!' marks a failing view)"),
        QStringLiteral("lock: the k⁺-buffer family's critical section (interlock = GL_ARB_fragment_shader_interlock); "
                       "--locks both measures each method that used interlock again with the spin-lock"),
        QStringLiteral("vs F2B, vs AB_LL: this method's time / theirs in this run (n/a: not run or not rendered); "
                       "vs ilock: a spin-lock cell's time / the same method's with interlock in this run"),
    };
}

QStringList benchTableLines(const BenchReport& report)
{
    QStringList titles;
    for (const Column& column : kColumns)
        titles << QString::fromLatin1(column.title);
    QStringList lines{formatRow(titles)};
    for (const BenchCell& cell : report.cells)
        lines << cellLine(report, cell);
    return lines;
}

QStringList benchFailureLines(const BenchReport& report)
{
    QStringList lines;
    for (const BenchCell& cell : report.cells) {
        if (!cell.failed())
            continue;
        const QString what = cell.violation.isEmpty()
                                 ? QStringLiteral("could not render: %1").arg(cell.error)
                                 : QStringLiteral("disagrees with the CPU reference: %1").arg(cell.violation);
        lines << QStringLiteral("%1 on %2 at %3 %4").arg(methodId(cell.method), cell.scene, sizeText(cell.size), what);
    }
    return lines;
}

} // namespace trimlab::app
