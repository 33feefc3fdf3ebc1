#include "app/skin_verb.h"

#include "app/output_paths.h"

#include "app/cli_messages.h"
#include "app/option_values.h"
#include "app/terminal_progress.h"

#include "core/animation/animation_loader.h"
#include "core/animation/animation_segmenter.h"
#include "core/animation/segment_count_search.h"
#include "core/animation/segment_sizes.h"
#include "core/skinning/skinning_fitter.h"
#include "core/skinning/skinning_gltf.h"

#include <QCommandLineParser>
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

struct SkinOptions {
    std::string source;
    QString output;
    std::size_t bones = 0;
    SkinningFitOptions fit;
    SkinExportOptions exported;
    double fps = 24.0;
    AnimationLoadOptions load;
};

void addSkinOptions(QCommandLineParser& parser)
{
    parser.setApplicationDescription(
        "Approximates a mesh animation by skinning: B proxy bones from a segmentation into exactly B segments, "
        "a fit of every pose, corrections, and a glTF 2.0 export. By default it fits the model a glTF skin plays "
        "(rigid joints, linear blend), which gives the lowest exported error. Prints E_RMS of the fit and of the "
        "exported file. See docs/skinning.md.");
    parser.addPositionalArgument("animation", "A folder of .obj/.ply/.off/.stl(.gz) poses, a pattern such as "
                                              "dir/mesh_%04d.obj.gz or dir/mesh_*.obj.gz, or a .gltf/.glb file.");
    parser.addOptions({
        {"bones", "Number of bones B (required, 1-65535): the animation is segmented into exactly B parts.", "B"},
        {"method", "rigid (rigid joints blended linearly, fitted with weight and rest updates: what the glTF "
                   "skin plays) | lbs (affine bone transforms, thesis 4.1) | dqs (rigid, dual quaternions). "
                   "Default: rigid.", "name"},
        {"chain", "lbs and dqs only: pose-to-pose (p2p-skinning, thesis 4.1) | rest-to-pose (classical). "
                  "Default: pose-to-pose. The rigid fit is always rest-to-pose.", "name"},
        {"corrections", "none | v (rest-pose vertex corrections) | w (weight corrections) | v,w. Default: v,w "
                        "for rigid, none for lbs and dqs.", "list"},
        {"influences", "Bones per vertex, 1-8, for the rigid fit and rest-to-pose LBS with corrections. Default: 4, "
                       "which every engine plays; 5-8 are written as JOINTS_1/WEIGHTS_1 (lower error on cloth-like "
                       "parts, but not every viewer reads them).", "N"},
        {"fps", "Frames per second of the exported animation (pose t at t/F seconds). Default: 24.", "F"},
        {"export", "rigid (a skin with one joint per bone) | morph (one morph target per pose, exact). "
                   "Default: rigid.", "kind"},
        {"interpolation", "linear | step: keyframe interpolation of the rigid export. Default: linear.", "name"},
        {"rest-pose", "Index of the rest pose among the loaded poses. Default: 0.", "I"},
        {"threads", "Worker threads (0 = all cores). Default: 0.", "N"},
        {{"o", "output"}, "Output file (required): .glb (binary) or .gltf (embedded buffer).", "file"},
    });
    parser.addHelpOption();
}

std::optional<QString> parseNumbers(const QCommandLineParser& parser, SkinOptions& options)
{
    long long bones = 0, restPose = 0, threads = 0, influences = static_cast<long long>(kDefaultInfluences);
    for (const auto& error : {parseIntegerFlag(parser, "bones", 1, 65535, bones),
                              parseIntegerFlag(parser, "influences", 1, static_cast<long long>(kMaxInfluences), influences),
                              parseIntegerFlag(parser, "rest-pose", 0, 1000000000, restPose),
                              parseIntegerFlag(parser, "threads", 0, 1024, threads)}) {
        if (error)
            return error;
    }
    options.bones = std::size_t(bones);
    options.fit.decomposition.maxInfluences = std::size_t(influences);
    options.load.restPose = std::size_t(restPose);
    options.load.threads = unsigned(threads);
    options.fit.threads = unsigned(threads);
    if (parser.isSet("fps")) {
        bool ok = false;
        options.fps = parser.value("fps").toDouble(&ok);
        if (!ok || !std::isfinite(options.fps) || options.fps < 1e-3 || options.fps > 10000.0)
            return QStringLiteral("--fps must be a number from 0.001 to 10000, got '%1'").arg(parser.value("fps"));
    }
    return std::nullopt;
}

std::optional<QString> parseMethod(const QCommandLineParser& parser, SkinOptions& options)
{
    const QString method = parser.isSet("method") ? parser.value("method") : QStringLiteral("rigid");
    if (method == "lbs" || method == "dqs")
        options.fit.method = method == "lbs" ? SkinningMethod::Lbs : SkinningMethod::Dqs;
    else if (method == "rigid")
        options.fit.fitExported = true;
    else
        return QStringLiteral("unknown --method '%1' (use rigid, lbs or dqs)").arg(method);
    const QString chain = parser.value("chain");
    if (parser.isSet("chain") && chain != "pose-to-pose" && chain != "rest-to-pose")
        return QStringLiteral("unknown --chain '%1' (use pose-to-pose or rest-to-pose)").arg(chain);
    if (parser.isSet("chain") && options.fit.fitExported)
        return QStringLiteral("--chain applies to --method lbs or dqs; the rigid fit always maps the rest pose to "
                              "each pose");
    options.fit.chain = chain == "rest-to-pose" || options.fit.fitExported ? SkinningChain::RestToPose
                                                                           : SkinningChain::PoseToPose;
    const QString defaultCorrections = options.fit.fitExported ? QStringLiteral("v,w") : QStringLiteral("none");
    const QString corrections = parser.isSet("corrections") ? parser.value("corrections") : defaultCorrections;
    if (corrections != "none" && corrections != "v" && corrections != "w" && corrections != "v,w" &&
        corrections != "w,v")
        return QStringLiteral("unknown --corrections '%1' (use none, v, w or v,w)").arg(corrections);
    options.fit.vertexCorrections = corrections.contains('v');
    options.fit.weightCorrections = corrections.contains('w');
    if (parser.isSet("influences") && !usesDecomposition(options.fit))
        return QStringLiteral("--influences applies to --method rigid (the default) and to --method lbs --chain "
                              "rest-to-pose with corrections; the other fits keep the segmentation's 4");
    return std::nullopt;
}

std::optional<QString> parseExport(const QCommandLineParser& parser, SkinOptions& options)
{
    const QString kind = parser.value("export");
    if (parser.isSet("export") && kind != "rigid" && kind != "morph")
        return QStringLiteral("unknown --export '%1' (use rigid or morph)").arg(kind);
    options.exported.morphTargets = kind == "morph";
    const QString interpolation = parser.value("interpolation");
    if (parser.isSet("interpolation") && interpolation != "linear" && interpolation != "step")
        return QStringLiteral("unknown --interpolation '%1' (use linear or step)").arg(interpolation);
    options.exported.stepInterpolation = interpolation == "step";
    options.output = parser.value("output");
    if (options.output.isEmpty())
        return QStringLiteral("skin needs an output file: -o out.glb (or .gltf)");
    if (!options.output.endsWith(".glb", Qt::CaseInsensitive) && !options.output.endsWith(".gltf", Qt::CaseInsensitive))
        return QStringLiteral("-o must name a .glb or .gltf file, got '%1'").arg(options.output);
    return checkOutputPaths({{"-o", options.output}});
}

std::variant<SkinOptions, QString> parseSkinOptions(const QStringList& arguments, QString& help)
{
    QCommandLineParser parser;
    addSkinOptions(parser);
    if (!parser.parse(QStringList{QStringLiteral("trimlab skin")} + arguments))
        return parser.errorText();
    if (parser.isSet("help")) {
        help = verbHelpText(parser, QStringLiteral("skin"));
        return QString();
    }
    if (parser.positionalArguments().size() != 1)
        return QStringLiteral("skin needs exactly one animation (a folder, a pattern or a glTF file); see trimlab skin "
                              "--help");
    if (!parser.isSet("bones"))
        return QStringLiteral("skin needs --bones B; see trimlab skin --help");
    SkinOptions options;
    options.source = parser.positionalArguments().first().toStdString();
    for (const auto& error : {parseNumbers(parser, options), parseMethod(parser, options), parseExport(parser, options)}) {
        if (error)
            return *error;
    }
    return options;
}

// Everything the summary prints.
struct SkinRun {
    std::size_t poses = 0, vertices = 0, faces = 0;
    SegmentCountSearch segmentation;
    SkinningFitResult fit;
    ExportedSkin exported;
    SkinningError exportedError;
    double loadMs = 0.0, segmentationMs = 0.0, exportMs = 0.0;
};

QString methodText(const SkinOptions& o)
{
    if (o.fit.fitExported)
        return QStringLiteral("rigid joints blended linearly (the glTF skin), rest-to-pose");
    QString text = o.fit.method == SkinningMethod::Lbs ? QStringLiteral("LBS") : QStringLiteral("DQS");
    text += o.fit.chain == SkinningChain::PoseToPose ? QStringLiteral(", pose-to-pose") : QStringLiteral(", rest-to-pose");
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
        .arg(s.sorted.front()).arg(s.sorted[s.sorted.size() / 2]).arg(s.sorted.back()).arg(s.underOnePercent)
        .arg(s.sorted.size());
}

void printSummary(const SkinOptions& o, const SkinRun& r)
{
    printLine(QStringLiteral("%1: %2 poses, %3 vertices, %4 faces")
                  .arg(QString::fromStdString(o.source)).arg(r.poses).arg(r.vertices).arg(r.faces));
    printLine(QStringLiteral("bones: %1 (segmentation: %2 clusters per pose, h = %3, %4 cleaned segments, %5 merged)")
                  .arg(r.segmentation.segmentation.count).arg(r.segmentation.clusters).arg(r.segmentation.h, 0, 'g', 4)
                  .arg(r.segmentation.cleanedCount).arg(r.segmentation.merged));
    printLine(segmentSizesText(r.segmentation.segmentation));
    printLine(QStringLiteral("method: %1; corrections: %2").arg(methodText(o), correctionsText(o, r.fit)) +
              (r.fit.iterations > 0 ? QStringLiteral("; %1 iterations").arg(r.fit.iterations) : QString()));
    printLine(QStringLiteral("E_RMS fit: %1 (E_RMS/diagonal %2; before corrections %3)")
                  .arg(r.fit.error.eRms, 0, 'f', 4).arg(r.fit.error.eRmsDiagonal, 0, 'g', 4)
                  .arg(r.fit.uncorrectedError.eRms, 0, 'f', 4));
    printLine(QStringLiteral("E_RMS exported: %1 (E_RMS/diagonal %2; %3, %4 joints)")
                  .arg(r.exportedError.eRms, 0, 'f', 4).arg(r.exportedError.eRmsDiagonal, 0, 'g', 4)
                  .arg(QString::fromLatin1(skinExportKindName(r.exported.kind).data())).arg(r.exported.joints));
    printLine(QStringLiteral("RMSE exported: %1 (per-vertex distance, length units, as Dem Bones prints it)")
                  .arg(r.exportedError.rmse, 0, 'g', 6));
    const SkinningStageTimes& t = r.fit.times;
    printLine(QStringLiteral("times (ms): load %1, segmentation %2, weights %3, fit %4, corrections %5, error %6, "
                             "export %7")
                  .arg(r.loadMs, 0, 'f', 1).arg(r.segmentationMs, 0, 'f', 1).arg(t.weightsMs, 0, 'f', 1)
                  .arg(t.fitMs, 0, 'f', 1).arg(t.weightCorrectionMs + t.vertexCorrectionMs, 0, 'f', 1)
                  .arg(t.errorMs, 0, 'f', 1).arg(r.exportMs, 0, 'f', 1));
}

// Segmentation errors name the animation ("walk: cannot make 500 segments of 120 vertices").
SegmentCountSearch segmentForBones(AnimationSegmenter& segmenter, const SkinOptions& o, const TaskControl& control)
{
    try {
        return segmentIntoCount(segmenter, o.bones, control);
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(o.source + ": " + e.what());
    } catch (const OperationCancelled&) {
        throw;
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(o.source + ": " + e.what());
    }
}

int skinAnimation(const SkinOptions& o)
{
    const TaskControl control = terminalProgress();
    SkinRun run;
    QElapsedTimer timer;
    timer.start();
    MeshAnimation loaded = loadAnimation(o.source, o.load, control);
    run.loadMs = lapMilliseconds(timer);
    SegmenterSettings settings;
    settings.partition.clusters = o.bones;
    settings.threads = o.fit.threads;
    AnimationSegmenter segmenter(std::move(loaded), settings);
    run.segmentation = segmentForBones(segmenter, o, control);
    run.segmentationMs = lapMilliseconds(timer);
    const MeshAnimation& animation = segmenter.animation();
    run.poses = animation.poseCount();
    run.vertices = animation.vertexCount();
    run.faces = animation.triangleCount();
    run.fit = fitSkinning(animation, run.segmentation.segmentation, o.fit, control);
    const std::vector<PosePositions> original = animationPositions(animation);
    timer.restart();
    SkinExportOptions exportOptions = o.exported;
    exportOptions.target = &original;
    run.exported = exportSkinnedGltf(run.fit.model, o.output.toStdString(), o.fps, exportOptions);
    run.exportMs = lapMilliseconds(timer);
    run.exportedError = measureSkinningError(original, run.exported.positions, animation.restPose);
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
    return runGuarded([&] { return skinAnimation(std::get<SkinOptions>(parsed)); });
}

} // namespace trimlab::app
