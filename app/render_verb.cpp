#include "app/render_verb.h"

#include "app/cli_messages.h"
#include "app/display_available.h"
#include "app/render_options.h"
#include "app/trim_exports.h"
#include "app/designed_frame.h"

#include "render/gl/context_reset.h"
#include "render/gl/gl_error.h"
#include "render/gl/offscreen_gl_context.h"
#include "core/animation/animation_chain.h"
#include "core/animation/animation_loader.h"
#include "core/animation/pose_history_plan.h"
#include "core/animation/pose_sets.h"
#include "core/catalog/pose_scene.h"
#include "core/catalog/scene_source.h"
#include "core/timeline/frame_chain.h"
#include "core/trim/dynamic_frame_scene.h"
#include "core/trim/dynamic_reference_renderer.h"
#include "core/trim/csg_expression.h"
#include "core/trim/reference_renderer.h"
#include "render/frame_times.h"
#include "render/trim_renderer.h"
#include "render/dynamic_trim_renderer.h"
#include "render/rgba_qimage.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QGuiApplication>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

namespace trimlab::app {

namespace {

struct RenderOutcome {
    QImage color;
    TrimImage trim;
    QString statistics;
};

QString framesText(int frames)
{
    return frames == 1 ? QStringLiteral("1 frame") : QStringLiteral("median of %1 frames").arg(frames);
}

// GPU times the driver flagged as implausible are left out of the GPU median.
QString timingText(const render::FrameTimes& times)
{
    const double gpuMs = times.medianGpuMilliseconds();
    return QStringLiteral("%1 ms GPU, %2 ms wall (%3)")
        .arg(gpuMs < 0.0 ? QStringLiteral("n/a") : QString::number(gpuMs, 'f', 2))
        .arg(times.medianWallMilliseconds(), 0, 'f', 2)
        .arg(framesText(times.frames()));
}

// "k+-buffer (max-array) (k = 16)": the method and the parameters it uses.
QString methodText(const render::MethodInfo& info, const render::MethodParameters& parameters)
{
    QStringList used;
    if (info.usesK)
        used << QStringLiteral("k = %1").arg(parameters.k);
    if (info.usesSharedCounters)
        used << QStringLiteral("S = %1").arg(parameters.sharedCounters);
    const QString name = QString::fromUtf8(info.displayName.data(), qsizetype(info.displayName.size()));
    return used.isEmpty() ? name : QStringLiteral("%1 (%2)").arg(name, used.join(QStringLiteral(", ")));
}

QString gpuStatistics(const render::FrameStats& s, const render::MethodParameters& parameters, const QString& renderer,
                      const render::FrameTimes& times)
{
    QString text = QStringLiteral("%1 on %2: %3, %4 geometry passes, %5 fragments, %6 stored, %7 lost, "
                                  "%8 overflowed pixels (%9 unresolved), %10 MB")
                       .arg(methodText(render::methodInfo(s.method), parameters), renderer, timingText(times))
                       .arg(s.methodStats.geometryPasses)
                       .arg(s.counts.fragmentsInSpan)
                       .arg(s.counts.fragmentsStored)
                       .arg(s.counts.fragmentsLost)
                       .arg(s.counts.overflowPixels)
                       .arg(s.counts.unresolvedPixels)
                       .arg(s.bufferMegabytes, 0, 'f', 1);
    if (s.methodStats.usesLock)
        text += QStringLiteral(", lock: %1").arg(QString::fromLatin1(render::lockDescription(s.methodStats)));
    if (s.counts.spinGiveUps > 0)
        text += QStringLiteral(", %1 fragments gave up on the spin-lock").arg(s.counts.spinGiveUps);
    return text;
}

void configure(render::TrimRenderer& renderer, const RenderOptions& options)
{
    render::MethodParameters parameters = renderer.parameters();
    parameters.k = options.parameters.k;
    parameters.sharedCounters = options.parameters.sharedCounters;
    parameters.memoryBudgetBytes = options.parameters.memoryBudgetBytes;
    renderer.setMethod(options.method);
    renderer.setParameters(parameters);
}

// `options.repeat` frames of `scene` on `renderer` (configured), timed.
RenderOutcome renderOn(render::TrimRenderer& renderer, const QString& rendererName, const Scene& scene,
                       const RenderOptions& options, const Camera& camera)
{
    renderer.setScene(scene);
    const render::MethodParameters parameters = renderer.parameters();
    render::FrameTimes times;
    for (int i = 0; i < options.repeat; ++i) {
        renderer.render(camera, options.trim, options.width, options.height);
        times.add(renderer.lastStats());
    }
    RenderOutcome outcome{renderer.readColor(), renderer.readTrimImage(), {}};
    outcome.statistics = gpuStatistics(renderer.lastStats(), parameters, rendererName, times);
    return outcome;
}

RenderOutcome renderWithGpu(const Scene& scene, const RenderOptions& options, const Camera& camera)
{
    render::OffscreenGlContext gl;
    render::TrimRenderer renderer(gl.context());
    configure(renderer, options);
    return renderOn(renderer, gl.capabilities().renderer, scene, options, camera);
}

// A GPU reset during the frames (gl/context_reset.h) takes the context and everything on
// it, but is usually transient (another application's fault, a driver watchdog): the
// frames are rendered once more on a new context, and a second reset is the error.
template <class RenderOnce>
RenderOutcome renderAgainAfterReset(RenderOnce&& renderOnce)
{
    try {
        return renderOnce();
    } catch (const render::GlContextLostError& e) {
        printNote(QStringLiteral("%1 Rendering again on a new OpenGL context (--backend reference renders on the CPU).")
                      .arg(QString::fromStdString(e.what())));
        return renderOnce();
    }
}

RenderOutcome renderWithReference(const Scene& scene, const RenderOptions& options, const Camera& camera)
{
    QElapsedTimer wall;
    wall.start();
    const ReferenceRenderer reference(scene);
    const double buildMs = double(wall.nsecsElapsed()) * 1e-6;
    std::vector<double> renderMs;
    ReferenceResult result;
    for (int i = 0; i < options.repeat; ++i) {
        result = reference.render(camera, options.width, options.height, options.trim, options.threads);
        renderMs.push_back(result.stats.wallMs);
    }
    RenderOutcome outcome{render::toQImage(result.color), std::move(result.trim), {}};
    outcome.statistics = QStringLiteral("reference ray caster: %1 ms wall (%2) on %3 threads (+ %4 ms BVH build), "
                                        "%5 hits, at most %6 per pixel")
                             .arg(render::medianOf(renderMs), 0, 'f', 2)
                             .arg(framesText(int(renderMs.size())))
                             .arg(result.stats.threads)
                             .arg(buildMs, 0, 'f', 2)
                             .arg(result.stats.totalHits)
                             .arg(result.stats.maxHitsPerPixel);
    return outcome;
}

// The chain levels of `step`: each pose against its reference pose, under its set's rule.
std::vector<DynamicChainLevel> historyLevels(const MeshAnimation& animation, const PoseHistoryStep& step)
{
    std::vector<DynamicChainLevel> levels;
    for (const PoseHistoryLevel& level : step.levels)
        levels.push_back(
            {makeDynamicFrameScene(animation.triangles, animation.poses[level.reference], animation.poses[level.pose]),
             level.rule});
    return levels;
}

// `options.repeat` frames of the chain's shown level on `renderer` (configured), after
// the step the pose history plan chose (core/animation/pose_history_plan.h) from the
// history `dynamic` rendered last: for Append and ReplaceShown `chain` holds only the
// levels that change — appended, so that only the new sets are characterized as the
// viewport's timeline does, or the new shown level, which keeps every characterization.
RenderOutcome renderDynamicOn(render::TrimRenderer& renderer, render::DynamicTrimRenderer& dynamic,
                              const QString& rendererName, const DynamicChain& chain, PoseHistoryStep::Kind step,
                              const RenderOptions& options, const Camera& camera)
{
    if (step == PoseHistoryStep::Kind::Append)
        for (const DynamicChainLevel& level : chain.levels)
            dynamic.appendLevel(level);
    else if (step == PoseHistoryStep::Kind::ReplaceShown)
        dynamic.setShownLevel(chain.levels.back());
    else
        dynamic.setChain(chain);
    render::FrameTimes times;
    double characterizeMs = 0.0;
    int characterized = 0;
    for (int i = 0; i < options.repeat; ++i) {
        dynamic.render(camera, options.trim, options.width, options.height);
        if (i == 0) {
            characterizeMs = dynamic.lastStats().characterizeMilliseconds;
            characterized = dynamic.lastStats().characterizedLevels;
        }
        times.add(renderer.lastStats());
    }
    RenderOutcome outcome{renderer.readColor(), withMeshIds(renderer.readTrimImage(), chain.levels.back().frame), {}};
    outcome.statistics = gpuStatistics(renderer.lastStats(), renderer.parameters(), rendererName, times) +
                         QStringLiteral("; dynamic rules: %1 sets, %2 ms to characterize %3 of them (the others "
                                        "cached), %4 moved triangles in the shown set")
                             .arg(dynamic.levelCount())
                             .arg(characterizeMs, 0, 'f', 2)
                             .arg(characterized)
                             .arg(chain.levels.back().frame.movedTriangles);
    return outcome;
}

RenderOutcome renderDynamicWithGpu(const DynamicChain& chain, const RenderOptions& options, const Camera& camera)
{
    render::OffscreenGlContext gl;
    render::TrimRenderer renderer(gl.context());
    configure(renderer, options);
    render::DynamicTrimRenderer dynamic(renderer);
    return renderDynamicOn(renderer, dynamic, gl.capabilities().renderer, chain, PoseHistoryStep::Kind::New, options,
                           camera);
}

RenderOutcome renderDynamicWithReference(const DynamicChain& chain, const RenderOptions& options, const Camera& camera)
{
    const DynamicReferenceRenderer reference(chain);
    ReferenceResult result;
    std::vector<double> renderMs;
    for (int i = 0; i < options.repeat; ++i) {
        result = reference.render(camera, options.width, options.height, options.trim, options.threads);
        renderMs.push_back(result.stats.wallMs);
    }
    RenderOutcome outcome{
        render::toQImage(result.color), withMeshIds(std::move(result.trim), chain.levels.back().frame), {}};
    outcome.statistics = QStringLiteral("reference ray caster, dynamic rules over %1 sets: %2 ms wall (%3)")
                             .arg(chain.levels.size())
                             .arg(render::medianOf(renderMs), 0, 'f', 2)
                             .arg(framesText(int(renderMs.size())));
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
                       .arg(QString::fromStdString(ruleName(options.trim.rule)),
                            QString::fromStdString(loaded.displayName), reason));
        return false;
    }
    printNote(QStringLiteral("rendering without trimming: %1").arg(reason));
    options.trim.trimEnabled = false;
    return true;
}

Camera cameraFor(const Bounds& bounds, const RenderOptions& options)
{
    if (options.camera)
        return withDepthRange(*options.camera, bounds);
    return fitCamera(bounds, double(options.width) / double(options.height));
}

void writeOutputs(const RenderOutcome& outcome, const RenderOptions& options, const Camera& camera)
{
    saveImage(outcome.color, options.output);
    if (!options.depthOutput.isEmpty())
        io::writePfm(options.depthOutput.toStdString(), rayDistanceImage(outcome.trim, camera));
    if (!options.idsOutput.isEmpty())
        saveImage(idImage(outcome.trim), options.idsOutput);
}

QString classificationText(const RenderOptions& options, const timeline::Timeline& timeline, int frame)
{
    const QString base = QString::fromStdString(ruleName(options.trim.rule));
    if (options.classification == Classification::Static)
        return options.trim.trimEnabled ? base + QStringLiteral(" (static)") : QStringLiteral("no trimming");
    QStringList rules;
    for (const timeline::Timeline::ChainLink& link : timeline.chainTo(frame))
        rules << QString::fromLatin1(dynamicRuleName(link.rule).data());
    if (rules.isEmpty())
        return QStringLiteral("dynamic: %1 on the base mesh (no deformation before this frame)").arg(base);
    return QStringLiteral("dynamic: %1 on the base mesh, then %2").arg(base, rules.join(QStringLiteral(", ")));
}

// A frame of a design: the sets' dynamic rules over the chain of reference frames, or
// the static rule on the frame alone.
int renderDesigned(const RenderOptions& given)
{
    const DesignedFrame design = loadDesignedFrame(given);
    RenderOptions options = given;
    const DesignedClassification chosen = designedClassification(given, design);
    options.classification = chosen.classification;
    options.trim.rule = chosen.rule;
    const bool gpu = options.backend == Backend::KPlus;
    RenderOutcome outcome;
    Camera camera;
    // The base mesh (frame 0, or every frame of a project with no frames yet) has no
    // deformation to remember: the dynamic rules classify it by the static base rule alone.
    const bool baseOnly = design.timeline.chainTo(design.frame).empty();
    if (options.classification == Classification::Static || baseOnly) {
        const Scene scene = timeline::frameScene(design.timeline, design.frame, design.model, design.displayName);
        camera = cameraFor(scene.worldBounds(), options);
        outcome = gpu ? renderAgainAfterReset([&] { return renderWithGpu(scene, options, camera); })
                      : renderWithReference(scene, options, camera);
    } else {
        const DynamicChain chain = timeline::frameChain(design.timeline, design.frame, options.trim.rule, design.model);
        camera = cameraFor(timeline::chainBounds(chain), options);
        outcome = gpu ? renderAgainAfterReset([&] { return renderDynamicWithGpu(chain, options, camera); })
                      : renderDynamicWithReference(chain, options, camera);
    }
    writeOutputs(outcome, options, camera);
    printLine(QStringLiteral("%1, frame %2 of %3: %4x%5, %6, %7 -> %8")
                  .arg(QString::fromStdString(design.displayName))
                  .arg(design.frame)
                  .arg(design.timeline.frameCount() - 1)
                  .arg(options.width)
                  .arg(options.height)
                  .arg(classificationText(options, design.timeline, design.frame), outcome.statistics, options.output));
    printLine(QStringLiteral("camera: %1").arg(QString::fromStdString(formatCamera(camera))));
    return 0;
}

// The cap pattern's spacing from the scene's size (--cap-spacing of its bounding radius), and the
// CSG expression and the object rules checked against the scene's objects. False (after
// printing why) when they name an object the scene lacks.
bool fitInspection(const Scene& scene, RenderOptions& options)
{
    const double radius = scene.worldBounds().radius();
    if (radius > 0.0)
        options.trim.cap.spacing = radius * options.capSpacingFraction;
    if (const std::optional<QString> error = checkObjectIds(options.trim.csg, scene.objects.size())) {
        printError(*error);
        return false;
    }
    return true;
}

// "alternating-border, CSG 0 | 1, capped": the classification and inspection settings.
QString settingsText(const TrimSettings& trim)
{
    QString text = trim.trimEnabled ? QString::fromStdString(ruleName(trim.rule)) : QStringLiteral("no trimming");
    if (trim.csg.enabled())
        text += QStringLiteral(", CSG %1").arg(QString::fromStdString(formatCsgExpression(trim.csg.expression)));
    if (trim.clipSet().enabledCount() > 1)
        text += QStringLiteral(", %1 clipping planes").arg(trim.clipSet().enabledCount());
    if (trim.capping())
        text += QStringLiteral(", capped");
    if (trim.xray())
        text +=
            QStringLiteral(", X-ray %1").arg(QString::fromLatin1(trimDisplayName(trim.transparency.display).data()));
    return text;
}

// Cap, collision and coplanar pixel counts of a rendered image (for the statistics line).
QString inspectionText(const TrimSettings& trim, const TrimImage& image)
{
    std::uint64_t caps = 0, collisions = 0, coplanar = 0;
    for (const TrimPixel& p : image.pixels) {
        caps += p.isCap() ? 1 : 0;
        collisions += p.collision ? 1 : 0;
        coplanar += p.coplanarCount >= 2 ? 1 : 0;
    }
    QStringList parts;
    if (trim.capping())
        parts << QStringLiteral("%1 cap pixels").arg(caps);
    if (trim.highlight.collisions)
        parts << QStringLiteral("%1 colliding pixels").arg(collisions);
    if (trim.highlight.coplanar)
        parts << QStringLiteral("%1 coplanar pixels").arg(coplanar);
    return parts.isEmpty() ? QString() : QStringLiteral("; ") + parts.join(QStringLiteral(", "));
}

// A scene project's saved rule, CSG and object rules, where the command line did not give
// its own. False (after printing why) when the saved CSG needs a method it did not choose.
bool adoptSavedSettings(const LoadedScene& loaded, RenderOptions& options)
{
    if (!options.ruleGiven && loaded.savedRule)
        options.trim.rule = *loaded.savedRule;
    CsgSettings& csg = options.trim.csg;
    const bool expressionGiven = csg.enabled();
    // --rule none has no interior to combine: the saved CSG stays unused.
    adoptSavedCsg(loaded, csg, expressionGiven, options.trim.trimEnabled);
    if (expressionGiven || !csg.enabled())
        return true;
    const render::MethodInfo& method = render::methodInfo(options.method);
    if (options.backend == Backend::KPlus && !method.inspection) {
        printError(QStringLiteral("%1 saved the CSG %2, which --method %3 cannot render; use a buffer method such as "
                                  "kplus-array or abuffer-linked-list")
                       .arg(QString::fromStdString(loaded.displayName),
                            QString::fromStdString(formatCsgExpression(csg.expression)),
                            QString::fromLatin1(method.id.data(), qsizetype(method.id.size()))));
        return false;
    }
    return true;
}

// "confluent against the previous pose (alternating-border on the rest pose 0)", or the
// static settings.
QString poseClassificationText(const RenderOptions& options, const MeshAnimation& animation, int pose)
{
    if (!options.poseRule)
        return settingsText(options.trim);
    const QString base = QString::fromStdString(ruleName(options.trim.rule));
    if (options.poseSets && std::size_t(pose) > animation.restPose) {
        const std::vector<PoseSet>& sets = *options.poseSets;
        const std::size_t set = setOfPose(sets, std::size_t(pose));
        return QStringLiteral("%1 against pose %2 (set %3 of %4 in %5; %6 on the rest pose %7)")
            .arg(QString::fromLatin1(dynamicRuleName(sets[set].rule).data()))
            .arg(sets[set].firstPose - 1)
            .arg(set + 1)
            .arg(sets.size())
            .arg(QString::fromStdString(poseSetsText(sets)), base)
            .arg(animation.restPose);
    }
    if (std::size_t(pose) == animation.restPose)
        return QStringLiteral("%1 (the rest pose: the base rule of %2)")
            .arg(base, QString::fromLatin1(dynamicRuleName(*options.poseRule).data()));
    return QStringLiteral("%1 against the %2 pose (%3 on the rest pose %4)")
        .arg(QString::fromLatin1(dynamicRuleName(*options.poseRule).data()),
             QString::fromLatin1(poseReferenceName(options.poseReference).data()), base)
        .arg(animation.restPose);
}

// --pose / --poses: the chosen poses of an animation under the static rule (or a dynamic
// rule over the animation as history), each to its own files, on one OpenGL context (or the CPU reference), with one camera fitted to all
// of them so that the images of a sequence line up.
int renderPoses(RenderOptions options)
{
    const std::string& source = options.sources.front();
    AnimationLoadOptions load;
    load.closeHoles = options.closeHoles;
    HoleClosing closing;
    const MeshAnimation animation = loadAnimation(source, load, {}, &closing);
    if (options.closeHoles)
        noteHolesClosed(std::filesystem::path(source).filename().string(), closing);
    const PoseSelection selection = *options.poses;
    const int count = int(animation.poseCount());
    if (selection.last >= count) {
        printError(QStringLiteral("%1 has %2 poses (0 to %3); pose %4 does not exist")
                       .arg(QString::fromStdString(source))
                       .arg(count)
                       .arg(count - 1)
                       .arg(selection.last));
        return 2;
    }
    const std::string name = std::filesystem::path(source).filename().string();
    std::vector<LoadedScene> poses;
    Bounds bounds;
    if (options.poseSets) {
        try {
            requireValidPoseSets(*options.poseSets, animation.restPose, animation.poseCount());
        } catch (const std::invalid_argument& e) {
            printError(
                QStringLiteral("--sets for %1: %2").arg(QString::fromStdString(source), QString::fromUtf8(e.what())));
            return 2;
        }
        if (std::size_t(selection.first) < animation.restPose) {
            printError(QStringLiteral("--sets cover the poses after the rest pose %1; pose %2 comes before it")
                           .arg(animation.restPose)
                           .arg(selection.first));
            return 2;
        }
    }
    options.ruleGiven = options.ruleGiven || options.poseRule.has_value(); // a dynamic rule cannot render untrimmed
    for (int pose = selection.first; pose <= selection.last; ++pose) {
        poses.push_back(animationPoseScene(animation, std::size_t(pose), name, name + " pose " + std::to_string(pose)));
        bounds.extend(poses.back().scene.worldBounds());
        if (!resolveTrimAvailability(poses.back(), options))
            return 1;
    }

    if (!fitInspection(poses.front().scene, options))
        return 2;
    const Camera camera = cameraFor(bounds, options);
    const bool gpu = options.backend == Backend::KPlus;
    std::unique_ptr<render::OffscreenGlContext> gl = gpu ? std::make_unique<render::OffscreenGlContext>() : nullptr;
    std::unique_ptr<render::TrimRenderer> renderer =
        gpu ? std::make_unique<render::TrimRenderer>(gl->context()) : nullptr;
    if (renderer)
        configure(*renderer, options);
    std::unique_ptr<render::DynamicTrimRenderer> dynamic =
        renderer ? std::make_unique<render::DynamicTrimRenderer>(*renderer) : nullptr;
    // The history's sets (--sets after the rest pose, or the reference's on both sides): a
    // pose that follows the one rendered before needs only its own level when the GPU
    // keeps the rest.
    const PoseHistorySets history = options.poseSets   ? PoseHistorySets{animation.restPose, *options.poseSets, {}}
                                    : options.poseRule ? referenceHistory(animation.restPose, animation.poseCount(),
                                                                          options.poseReference, *options.poseRule)
                                                       : PoseHistorySets{};
    std::optional<std::size_t> held; // the pose whose chain `dynamic` holds
    for (std::size_t i = 0; i < poses.size(); ++i) {
        const int pose = selection.first + int(i);
        RenderOutcome outcome;
        if (options.poseRule && std::size_t(pose) != animation.restPose) {
            const PoseHistoryStep step = planPoseHistory(history, held, std::size_t(pose));
            const DynamicChain chain =
                step.kind != PoseHistoryStep::Kind::New
                    ? DynamicChain{options.trim.rule, historyLevels(animation, step)}
                : options.poseSets ? *poseSetChain(animation, std::size_t(pose), *options.poseSets, options.trim.rule)
                                   : *animationChain(animation, std::size_t(pose), options.poseReference,
                                                     *options.poseRule, options.trim.rule);
            outcome = renderer ? renderDynamicOn(*renderer, *dynamic, gl->capabilities().renderer, chain, step.kind,
                                                 options, camera)
                               : renderDynamicWithReference(chain, options, camera);
            held = renderer ? std::optional(std::size_t(pose)) : std::nullopt;
        } else {
            held.reset();
            outcome = renderer ? renderOn(*renderer, gl->capabilities().renderer, poses[i].scene, options, camera)
                               : renderWithReference(poses[i].scene, options, camera);
        }
        RenderOptions files = options;
        files.output = posePath(options.output, pose);
        files.depthOutput = posePath(options.depthOutput, pose);
        files.idsOutput = posePath(options.idsOutput, pose);
        writeOutputs(outcome, files, camera);
        printLine(QStringLiteral("%1, pose %2 of %3: %4x%5, %6, %7 -> %8")
                      .arg(QString::fromStdString(name))
                      .arg(pose)
                      .arg(count - 1)
                      .arg(options.width)
                      .arg(options.height)
                      .arg(poseClassificationText(options, animation, pose))
                      .arg(outcome.statistics + inspectionText(options.trim, outcome.trim), files.output));
    }
    printLine(QStringLiteral("camera: %1").arg(QString::fromStdString(formatCamera(camera))));
    return 0;
}

int renderLoaded(RenderOptions options)
{
    if (options.poses)
        return renderPoses(options);
    if (options.designed())
        return renderDesigned(options);
    LoadedScene loaded = loadScenes(options.sources);
    if (options.closeHoles)
        closeHolesNoted(loaded);
    if (const std::optional<QString> error = applyObjectTransforms(options.objectTransforms, loaded.scene)) {
        printError(*error);
        return 2;
    }
    if (!adoptSavedSettings(loaded, options))
        return 2;
    if (!resolveTrimAvailability(loaded, options))
        return 1;
    if (!fitInspection(loaded.scene, options))
        return 2;
    const Camera camera = cameraFor(loaded.scene.worldBounds(), options);
    const RenderOutcome outcome =
        options.backend == Backend::KPlus
            ? renderAgainAfterReset([&] { return renderWithGpu(loaded.scene, options, camera); })
            : renderWithReference(loaded.scene, options, camera);
    writeOutputs(outcome, options, camera);
    printLine(QStringLiteral("%1: %2x%3, %4, %5 -> %6")
                  .arg(QString::fromStdString(loaded.displayName))
                  .arg(options.width)
                  .arg(options.height)
                  .arg(settingsText(options.trim))
                  .arg(outcome.statistics + inspectionText(options.trim, outcome.trim), options.output));
    printLine(QStringLiteral("camera: %1").arg(QString::fromStdString(formatCamera(camera))));
    return 0;
}

} // namespace

int runRenderVerb(int argc, char** argv, const QStringList& arguments)
{
    QString help;
    auto parsed = parseRenderOptions(arguments, &help);
    if (const std::optional<int> exitCode = exitIfNotParsed(parsed, help))
        return *exitCode;
    const RenderOptions& options = std::get<RenderOptions>(parsed);
    std::unique_ptr<QCoreApplication> application;
    if (options.backend == Backend::KPlus) {
        if (!displayAvailable()) {
            printError("the OpenGL backend needs a display; run under 'xvfb-run -a' or use --backend reference");
            return 1;
        }
        application = std::make_unique<QGuiApplication>(argc, argv);
    } else {
        application = std::make_unique<QCoreApplication>(argc, argv);
    }
    return runGuarded([&] { return renderLoaded(options); }, options.sources);
}

} // namespace trimlab::app
