#include "app/segment_verb.h"

#include "app/cli_messages.h"
#include "app/segment_options.h"

#include "core/animation/animation_loader.h"
#include "core/animation/segmentation_record.h"
#include "core/animation/segmentation_run.h"

#include <QCoreApplication>
#include <QElapsedTimer>

#include <cmath>
#include <optional>
#include <variant>

namespace trimlab::app {

namespace {

double elapsedMs(const QElapsedTimer& timer)
{
    return double(timer.nsecsElapsed()) * 1e-6;
}

// Refusals name the animation ("walk: the animation has 1 pose; ...").
std::shared_ptr<const SegmentationResult> segmentLoaded(MeshAnimation animation, const SegmentOptions& options)
{
    SegmentationRunOptions run;
    run.settings = options.settings;
    run.variable = false; // the record adds it in variable mode
    try {
        return runSegmentation(std::move(animation), run);
    } catch (const SegmentationInputError& e) {
        throw std::runtime_error(options.source + ": " + e.what());
    }
}

void printSummary(const SegmentationRecord& r)
{
    printLine(QStringLiteral("%1: %2 poses, %3 vertices, %4 faces; %5 (%6), %7, %8 clusters per pose")
                  .arg(QString::fromStdString(r.source))
                  .arg(r.poseCount)
                  .arg(r.vertexCount)
                  .arg(r.faceCount)
                  .arg(QString::fromLatin1(featureName(r.feature.kind).data()),
                       QString::fromLatin1(referenceName(r.feature.reference).data()),
                       QString::fromLatin1(partitionMethodName(r.partition.method).data()))
                  .arg(r.partition.clusters));
    printLine(QStringLiteral("segments: %1 (over-segmentation %2, h = %3)")
                  .arg(r.segmentation.count)
                  .arg(r.overSegmentCount)
                  .arg(r.h));
    printLine(QStringLiteral("times (ms): load %1, features %2, partitions %3, over-segmentation %4, cleaning %5")
                  .arg(r.times.load, 0, 'f', 1)
                  .arg(r.times.features, 0, 'f', 1)
                  .arg(r.times.partitions, 0, 'f', 1)
                  .arg(r.times.overSegmentation, 0, 'f', 1)
                  .arg(r.times.cleaning, 0, 'f', 2));
}

int segmentAnimation(const SegmentOptions& options)
{
    QElapsedTimer timer;
    timer.start();
    HoleClosing closing;
    MeshAnimation animation = loadAnimation(options.source, options.load, {}, &closing);
    if (options.load.closeHoles)
        noteHolesClosed(options.source, closing);
    const double loadMs = elapsedMs(timer);
    const std::shared_ptr<const SegmentationResult> result = segmentLoaded(std::move(animation), options);
    const AnimationSegmenter& segmenter = *result->segmenter;
    timer.restart();
    VertexLabeling segmentation = segmenter.segment(options.h);
    const double cleaningMs = elapsedMs(timer);
    SegmentationRecord record =
        makeSegmentationRecord(segmenter, options.source, options.h, std::move(segmentation), {}, options.variableMode);
    record.times.load = loadMs;
    record.times.cleaning = cleaningMs;
    writeSegmentationFile(options.output.toStdString(), options.format, record, segmenter.animation());
    printSummary(record);
    printLine(QStringLiteral("wrote %1").arg(options.output));
    return 0;
}

} // namespace

int runSegmentVerb(int argc, char** argv, const QStringList& arguments)
{
    QCoreApplication application(argc, argv);
    QString help;
    const auto parsed = parseSegmentOptions(arguments, help);
    if (const std::optional<int> code = exitIfNotParsed(parsed, help))
        return *code;
    const SegmentOptions& options = std::get<SegmentOptions>(parsed);
    return runGuarded([&] { return segmentAnimation(options); }, {options.source});
}

} // namespace trimlab::app
