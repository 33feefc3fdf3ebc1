#include "app/skin_verb.h"

#include "app/cli_messages.h"
#include "app/skin_options.h"
#include "app/terminal_progress.h"

#include "core/animation/animation_loader.h"
#include "core/animation/segment_sizes.h"
#include "core/skinning/skinning_error.h"
#include "core/skinning/skinning_gltf.h"
#include "core/skinning/skinning_pipeline.h"

#include <QCoreApplication>
#include <QElapsedTimer>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <variant>

namespace trimlab::app {

namespace {

// Everything the summary prints.
struct SkinRun {
    std::size_t poses = 0, vertices = 0, faces = 0;
    std::shared_ptr<const SkinningFit> fit;
    ExportedSkin exported;
    SkinningError exportedError;
    double loadMs = 0.0, exportMs = 0.0;
};

QString methodText(const SkinOptions& o)
{
    if (o.fit.fitExported)
        return QStringLiteral("rigid joints blended linearly (the glTF skin), rest-to-pose");
    QString text = o.fit.method == SkinningMethod::Lbs ? QStringLiteral("LBS") : QStringLiteral("DQS");
    text +=
        o.fit.chain == SkinningChain::PoseToPose ? QStringLiteral(", pose-to-pose") : QStringLiteral(", rest-to-pose");
    return text;
}

QString correctionsText(const SkinOptions& o, const SkinningFitResult& fit)
{
    if (!o.fit.vertexCorrections && !o.fit.weightCorrections)
        return QStringLiteral("none");
    QStringList parts;
    if (o.fit.vertexCorrections)
        parts << (fit.vertexCorrectionsKept ? QStringLiteral("v (kept)") : QStringLiteral("v (dropped: no gain)"));
    if (o.fit.weightCorrections)
        parts << (fit.weightCorrectionsKept ? QStringLiteral("w (kept)") : QStringLiteral("w (dropped: no gain)"));
    return parts.join(", ");
}

// Segments far below the average size spend a bone on little of the mesh: say how the
// vertices are spread over the segments the bones come from.
QString segmentSizesText(const VertexLabeling& segmentation)
{
    const SegmentSizes s = segmentSizes(segmentation);
    return QStringLiteral("segment sizes (vertices): smallest %1, median %2, largest %3; %4 of %5 under 1 %")
        .arg(s.sorted.front())
        .arg(s.sorted[s.sorted.size() / 2])
        .arg(s.sorted.back())
        .arg(s.underOnePercent)
        .arg(s.sorted.size());
}

void printSummary(const SkinOptions& o, const SkinRun& r)
{
    const SegmentCountSearch& search = *r.fit->search;
    const SkinningFitResult& fit = r.fit->result;
    printLine(QStringLiteral("%1: %2 poses, %3 vertices, %4 faces")
                  .arg(QString::fromStdString(o.source))
                  .arg(r.poses)
                  .arg(r.vertices)
                  .arg(r.faces));
    printLine(QStringLiteral("bones: %1 (segmentation: %2 clusters per pose, h = %3, %4 cleaned segments, %5 merged)")
                  .arg(r.fit->bones.count)
                  .arg(search.clusters)
                  .arg(search.h, 0, 'g', 4)
                  .arg(search.cleanedCount)
                  .arg(search.merged));
    printLine(segmentSizesText(r.fit->bones));
    printLine(QStringLiteral("method: %1; corrections: %2").arg(methodText(o), correctionsText(o, fit)) +
              (fit.iterations > 0 ? QStringLiteral("; %1 iterations").arg(fit.iterations) : QString()));
    printLine(QStringLiteral("E_RMS fit: %1 (E_RMS/diagonal %2; before corrections %3)")
                  .arg(fit.error.eRms, 0, 'f', 4)
                  .arg(fit.error.eRmsDiagonal, 0, 'g', 4)
                  .arg(fit.uncorrectedError.eRms, 0, 'f', 4));
    printLine(QStringLiteral("E_RMS exported: %1 (E_RMS/diagonal %2; %3, %4 joints)")
                  .arg(r.exportedError.eRms, 0, 'f', 4)
                  .arg(r.exportedError.eRmsDiagonal, 0, 'g', 4)
                  .arg(QString::fromLatin1(skinExportKindName(r.exported.kind).data()))
                  .arg(r.exported.joints));
    printLine(QStringLiteral("RMSE exported: %1 (per-vertex distance, length units, as Dem Bones prints it)")
                  .arg(r.exportedError.rmse, 0, 'g', 6));
    const SkinningStageTimes& t = fit.times;
    printLine(QStringLiteral("times (ms): load %1, segmentation %2, weights %3, fit %4, corrections %5, error %6, "
                             "export %7")
                  .arg(r.loadMs, 0, 'f', 1)
                  .arg(r.fit->segmentationMs, 0, 'f', 1)
                  .arg(t.weightsMs, 0, 'f', 1)
                  .arg(t.fitMs, 0, 'f', 1)
                  .arg(t.weightCorrectionMs + t.vertexCorrectionMs, 0, 'f', 1)
                  .arg(t.errorMs, 0, 'f', 1)
                  .arg(r.exportMs, 0, 'f', 1));
}

// Errors making the bones name the animation ("walk: cannot make 500 segments of 120 vertices").
std::shared_ptr<const SkinningFit> fitAnimation(const MeshAnimation& animation, const SkinOptions& o,
                                                const TaskControl& control)
{
    const SkinningBoneSource bones = segmentedBones(o.bones, o.fit.threads);
    SkinningPipelineOptions options;
    options.fit = o.fit;
    options.reconstruct = false; // the export measures its own file
    try {
        return runSkinningFit(animation, bones, options, control);
    } catch (const SkinningBonesError& e) {
        throw std::runtime_error(o.source + ": " + e.what());
    }
}

int skinAnimation(const SkinOptions& o)
{
    const TaskControl control = terminalProgress();
    SkinRun run;
    QElapsedTimer timer;
    timer.start();
    HoleClosing closing;
    const MeshAnimation animation = loadAnimation(o.source, o.load, control, &closing);
    if (o.load.closeHoles)
        noteHolesClosed(o.source, closing);
    run.loadMs = lapMilliseconds(timer);
    run.poses = animation.poseCount();
    run.vertices = animation.vertexCount();
    run.faces = animation.triangleCount();
    run.fit = fitAnimation(animation, o, control);
    timer.restart();
    SkinExportOptions exportOptions = o.exported;
    exportOptions.target = &run.fit->original;
    run.exported = exportSkinnedGltf(run.fit->result.model, o.output.toStdString(), o.fps, exportOptions);
    run.exportMs = lapMilliseconds(timer);
    run.exportedError = measureSkinningError(run.fit->original, run.exported.positions, animation.restPose);
    printSummary(o, run);
    printLine(QStringLiteral("wrote %1").arg(o.output));
    return 0;
}

} // namespace

int runSkinVerb(int argc, char** argv, const QStringList& arguments)
{
    QCoreApplication application(argc, argv);
    QString help;
    const auto parsed = parseSkinOptions(arguments, help);
    if (const std::optional<int> code = exitIfNotParsed(parsed, help))
        return *code;
    const SkinOptions& options = std::get<SkinOptions>(parsed);
    return runGuarded([&] { return skinAnimation(options); }, {options.source});
}

} // namespace trimlab::app
