#include "app/bench_json.h"

#include "core/io/atomic_write.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <stdexcept>

namespace trimlab::app {

namespace {

QString sizeText(QSize size)
{
    return QStringLiteral("%1x%2").arg(size.width()).arg(size.height());
}

QJsonValue optionalNumber(const std::optional<double>& value)
{
    return value ? QJsonValue(*value) : QJsonValue(QJsonValue::Null);
}

QJsonObject headerObject(const BenchHeader& header)
{
    QJsonArray sizes;
    for (const QSize size : header.sizes)
        sizes.append(sizeText(size));
    QJsonArray methods;
    for (const render::FragmentMethodKind method : header.methods)
        methods.append(methodId(method));
    return {
        {"version", header.version}, {"openGl", header.openGl},  {"cpuThreads", int(header.cpuThreads)},
        {"date", header.date},       {"sizes", sizes},           {"views", header.views},
        {"repeat", header.repeat},   {"k", header.parameters.k}, {"sharedCounters", header.parameters.sharedCounters},
        {"locks", header.locks},     {"methods", methods},       {"scenes", QJsonArray::fromStringList(header.scenes)}};
}

QString status(const BenchCell& cell)
{
    if (!cell.rendered())
        return cell.outOfMemory     ? QStringLiteral("out-of-memory")
               : cell.notApplicable ? QStringLiteral("not-applicable")
                                    : QStringLiteral("failed");
    return cell.violation.isEmpty() ? QStringLiteral("ok") : QStringLiteral("disagrees");
}

void addMeasurements(QJsonObject& object, const BenchReport& report, const BenchCell& cell)
{
    const TrimAgreement& a = cell.agreement;
    const std::string_view source = cell.times.source();
    object.insert("msPerFrame", cell.times.medianMilliseconds());
    object.insert("timeSource", QString::fromLatin1(source.data(), qsizetype(source.size())));
    object.insert("gpuMsMedian", cell.times.gpuTimed() ? QJsonValue(cell.times.medianGpuMilliseconds()) : QJsonValue());
    object.insert("wallMsMedian", cell.times.medianWallMilliseconds());
    object.insert("pipelinedMsPerFrame", pipelinedMilliseconds(cell));
    object.insert("pipelinedToGpu", optionalNumber(pipelinedToGpu(cell)));
    object.insert("frames", cell.times.frames());
    object.insert("views", cell.views);
    object.insert("geometryPasses", cell.geometryPasses);
    object.insert("fullscreenPasses", cell.fullscreenPasses);
    object.insert("megabytes", cell.megabytes);
    object.insert("interlock", cell.interlock);
    object.insert("lock", lockId(cell));
    object.insert("fragmentsInSpan", double(cell.fragmentsInSpan));
    object.insert("fragmentsStored", double(cell.fragmentsStored));
    object.insert("fragmentsLost", double(cell.fragmentsLost));
    object.insert("overflowPixels", double(cell.overflowPixels));
    object.insert("unresolvedPixels", double(cell.unresolvedPixels));
    object.insert("spinGiveUps", double(cell.spinGiveUps));
    object.insert("agreementPercent", 100.0 * a.agreement());
    object.insert("worstViewAgreementPercent", 100.0 * cell.worstViewAgreement);
    object.insert("comparedPixels", a.compared());
    object.insert("excludedPercent", 100.0 * a.excludedFraction());
    object.insert("overflowedPixelsNotCompared", a.overflowed);
    object.insert("violation", cell.violation.isEmpty() ? QJsonValue() : QJsonValue(cell.violation));
    object.insert("ratioToF2B",
                  optionalNumber(timeRatio(cell, findCell(report, cell, render::FragmentMethodKind::PeelingF2B))));
    object.insert("ratioToABLL", optionalNumber(timeRatio(
                                     cell, findCell(report, cell, render::FragmentMethodKind::ABufferLinkedList))));
    object.insert("ratioToInterlock", cell.usesLock && !cell.interlock
                                          ? optionalNumber(timeRatio(cell, findInterlockCell(report, cell)))
                                          : QJsonValue());
}

QJsonObject cellObject(const BenchReport& report, const BenchCell& cell)
{
    const render::MethodInfo& info = render::methodInfo(cell.method);
    QJsonObject object{{"scene", cell.scene},
                       {"size", sizeText(cell.size)},
                       {"width", cell.size.width()},
                       {"height", cell.size.height()},
                       {"method", methodId(cell.method)},
                       {"methodName", QString::fromUtf8(info.displayName.data(), qsizetype(info.displayName.size()))},
                       {"bounded", info.bounded},
                       {"status", status(cell)},
                       {"error", cell.error.isEmpty() ? QJsonValue() : QJsonValue(cell.error)}};
    if (cell.rendered())
        addMeasurements(object, report, cell);
    return object;
}

} // namespace

QByteArray benchJson(const BenchReport& report)
{
    QJsonArray skipped;
    for (const BenchSkip& skip : report.skipped)
        skipped.append(QJsonObject{{"scene", skip.scene}, {"reason", skip.reason}});
    QJsonArray results;
    for (const BenchCell& cell : report.cells)
        results.append(cellObject(report, cell));
    const QJsonObject root{{"header", headerObject(report.header)}, {"skipped", skipped}, {"results", results}};
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

void writeBenchJson(const BenchReport& report, const QString& path)
{
    // Through a temporary file and a rename: a killed run leaves an earlier report whole.
    const QByteArray json = benchJson(report);
    io::writeFileAtomically(path.toStdString(), std::string_view(json.constData(), std::size_t(json.size())));
}

} // namespace trimlab::app
