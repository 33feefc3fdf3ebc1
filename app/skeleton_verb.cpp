#include "app/skeleton_verb.h"

#include "app/cli_messages.h"
#include "app/scene_composition.h"
#include "app/skeleton_options.h"
#include "app/terminal_progress.h"

#include "core/animation/animation_loader.h"
#include "core/mesh/loop_subdivision.h"
#include "core/catalog/scene_source.h"
#include "core/scene/world_geometry.h"
#include "core/skeleton/rig_motion_fit.h"
#include "core/skeleton/rigged_gltf.h"
#include "core/skeleton/skeleton_input.h"
#include "core/skeleton/skeleton_json.h"
#include "core/skeleton/skeleton_pipeline.h"

#include <QCoreApplication>
#include <QElapsedTimer>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace trimlab::app {

namespace {

// The mesh of a one-object source, in world coordinates, its holes closed when asked.
TriangleMesh loadSingleMesh(const std::string& source, bool closeHoles)
{
    LoadedScene loaded = loadScene(source);
    if (closeHoles)
        closeHolesNoted(loaded);
    if (loaded.scene.objects.size() != 1)
        throw std::runtime_error(source + ": has " + std::to_string(loaded.scene.objects.size()) +
                                 " objects; the skeleton verb takes one mesh");
    const SceneObject& object = loaded.scene.objects.front();
    TriangleMesh mesh = object.mesh;
    const std::vector<glm::dvec3> world = worldPositions(object);
    for (std::size_t v = 0; v < world.size(); ++v)
        mesh.positions[v] = glm::vec3(world[v]);
    return mesh;
}

// The rest pose of an animation as the mesh to rig, and every pose for the motion fit.
struct AnimationInput {
    TriangleMesh mesh;
    std::vector<PosePositions> poses;
    std::size_t restPose = 0;
};

AnimationInput loadAnimationInput(const SkeletonVerbOptions& o)
{
    AnimationLoadOptions load;
    load.restPose = o.restPose;
    load.closeHoles = o.closeHoles;
    HoleClosing closing;
    const MeshAnimation animation = loadAnimation(o.source, load, terminalProgress(), &closing);
    if (o.closeHoles)
        noteHolesClosed(o.source, closing);
    return {animation.poseMesh(animation.restPose), animationPositions(animation), animation.restPose};
}

// Everything the summary prints.
struct SkeletonRun {
    std::size_t inputVertices = 0, vertices = 0, faces = 0, poses = 0, restPose = 0;
    double loadMs = 0.0, subdivisionMs = 0.0, exportMs = 0.0;
    SkeletonResult result;
    std::optional<RigMotionFit> motion; ///< animations only
};

QString seconds(double ms)
{
    return QString::number(ms * 1e-3, 'f', 3);
}

// The evaluator's numbers (skeleton_evaluation.h) for the curve skeleton and the rig.
void printQuality(const SkeletonRun& r)
{
    printLine(QStringLiteral("quality of the curve skeleton and of the rig (evaluated in %1 s; lengths x the "
                             "bounding-box diagonal %2):")
                  .arg(seconds(r.result.evaluationMs))
                  .arg(r.result.curveQuality.diagonal, 0, 'g', 4));
    for (const auto& [name, quality] :
         {std::pair{"curve", &r.result.curveQuality}, std::pair{"rig", &r.result.rigQuality}})
        for (const std::string& line : describeEvaluation(*quality))
            printLine(QStringLiteral("  %1 %2").arg(QString::fromLatin1(name), -5).arg(QString::fromStdString(line)));
    printLine(
        QStringLiteral("  rig   posing: %1").arg(QString::fromStdString(describeRigMeasures(r.result.rigMeasures))));
    if (r.motion)
        printLine(QStringLiteral("  rig   motion: %1").arg(QString::fromStdString(describeRigMotionFit(*r.motion))));
}

void printSummary(const SkeletonVerbOptions& o, const SkeletonRun& r)
{
    QString mesh =
        QStringLiteral("%1: %2 vertices, %3 faces").arg(QString::fromStdString(o.source)).arg(r.vertices).arg(r.faces);
    if (o.animation)
        mesh += QStringLiteral(" (the rest pose %1 of %2 poses)").arg(r.restPose).arg(r.poses);
    if (o.loopLevels > 0)
        mesh += QStringLiteral(" (Loop-subdivided %1x from %2 vertices in %3 s)")
                    .arg(o.loopLevels)
                    .arg(r.inputVertices)
                    .arg(seconds(r.subdivisionMs));
    printLine(mesh + QStringLiteral("; loaded in %1 s").arg(seconds(r.loadMs)));
    const SkeletonExtraction& extraction = *r.result.extraction;
    const SkeletonRig& rig = r.result.rig;
    printLine(QStringLiteral("skeleton: %1 joints, %2 bones, root joint %3; curve skeleton %4 nodes, %5 edges")
                  .arg(rig.joints.size())
                  .arg(rig.bones.size())
                  .arg(rig.root)
                  .arg(extraction.curve.nodes.size())
                  .arg(extraction.curve.edges.size()));
    printLine(QStringLiteral("contraction: %1 iterations, %2 symbolic analysis(es), %3 numeric factorizations; %4")
                  .arg(extraction.contractionIterations)
                  .arg(extraction.symbolicAnalyses)
                  .arg(extraction.numericFactorizations)
                  .arg(QString::fromStdString(extraction.solver)));
    for (const std::string& warning : extraction.warnings)
        printNote(QString::fromStdString(warning));
    const BoneHeatReport& weights = r.result.weights->report();
    printLine(QStringLiteral("weights: %1; %2 vertices without a visible bone, %3 pinned to their nearest bone")
                  .arg(QString::fromStdString(weights.factorization))
                  .arg(weights.hiddenVertices)
                  .arg(weights.pinnedVertices));
    if (!weights.note.empty())
        printNote(QString::fromStdString(weights.note));
    const SkeletonStageTimes& t = r.result.times;
    const double total = r.result.totalMs() + r.exportMs;
    // The columns of the paper's Table III (times in seconds), each as wide as its name.
    const std::vector<std::pair<QString, QString>> columns = {
        {"vertices", QString::number(r.vertices)},
        {"iterations", QString::number(extraction.contractionIterations)},
        {"contraction", seconds(t.contractionMs)},
        {"simplification", seconds(t.simplificationMs)},
        {"refinement", seconds(t.refinementMs)},
        {"selection", seconds(t.selectionMs)},
        {"weights", seconds(r.result.weightsMs)},
        {"export", seconds(r.exportMs)},
        {"total", seconds(total)},
    };
    QString header, row;
    for (const auto& [name, value] : columns) {
        const int width = int(std::max(name.size(), value.size())) + 2;
        header += name.rightJustified(width);
        row += value.rightJustified(width);
    }
    printLine(QStringLiteral("times (s):") + header);
    printLine(QStringLiteral("          ") + row);
    printQuality(r);
}

// Refusals name the mesh ("cat.obj: the mesh is open: ...").
SkeletonResult runPipeline(const TriangleMesh& mesh, const SkeletonVerbOptions& o)
{
    try {
        SkeletonPipelineOptions options;
        options.extraction = o.extraction;
        options.heatConstant = o.heatConstant;
        return runSkeletonPipeline(mesh, options, terminalProgress());
    } catch (const SkeletonInputError& e) {
        throw std::runtime_error(o.source + ": " + e.what());
    }
}

void exportResults(const TriangleMesh& mesh, const SkeletonVerbOptions& o, const SkeletonResult& r)
{
    if (!o.output.isEmpty())
        exportRiggedGltf(mesh, r.rig, r.weights->weights(), o.output.toStdString());
    if (!o.json.isEmpty())
        saveSkeletonJson(o.json.toStdString(), r.rig, &r.extraction->curve);
}

int skeletonOfMesh(const SkeletonVerbOptions& o)
{
    SkeletonRun run;
    QElapsedTimer timer;
    timer.start();
    std::optional<AnimationInput> animation;
    if (o.animation)
        animation = loadAnimationInput(o);
    TriangleMesh mesh = animation ? std::move(animation->mesh) : loadSingleMesh(o.source, o.closeHoles);
    run.loadMs = lapMilliseconds(timer);
    run.inputVertices = mesh.vertexCount();
    if (o.loopLevels > 0) {
        mesh = loopSubdivide(mesh, o.loopLevels);
        run.subdivisionMs = lapMilliseconds(timer);
    }
    run.vertices = mesh.vertexCount();
    run.faces = mesh.triangleCount();
    run.result = runPipeline(mesh, o);
    if (animation) {
        run.poses = animation->poses.size();
        run.restPose = animation->restPose;
        run.motion = fitRigToMotion(run.result.rig, run.result.weights->weights(), animation->poses,
                                    animation->restPose, {}, terminalProgress());
    }
    timer.restart();
    exportResults(mesh, o, run.result);
    run.exportMs = lapMilliseconds(timer);
    printSummary(o, run);
    for (const QString& file : {o.output, o.json})
        if (!file.isEmpty())
            printLine(QStringLiteral("wrote %1").arg(file));
    return 0;
}

} // namespace

int runSkeletonVerb(int argc, char** argv, const QStringList& arguments)
{
    QCoreApplication application(argc, argv);
    QString help;
    const auto parsed = parseSkeletonOptions(arguments, help);
    if (const std::optional<int> code = exitIfNotParsed(parsed, help))
        return *code;
    const SkeletonVerbOptions& options = std::get<SkeletonVerbOptions>(parsed);
    return runGuarded([&] { return skeletonOfMesh(options); }, {options.source});
}

} // namespace trimlab::app
