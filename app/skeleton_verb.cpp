#include "app/skeleton_verb.h"

#include "app/output_paths.h"

#include "app/cli_messages.h"
#include "app/option_values.h"
#include "app/terminal_progress.h"

#include "core/mesh/loop_subdivision.h"
#include "core/catalog/scene_source.h"
#include "core/scene/world_geometry.h"
#include "core/skeleton/bone_heat_weights.h"
#include "core/skeleton/rigged_gltf.h"
#include "core/skeleton/skeleton_evaluation.h"
#include "core/skeleton/skeleton_extraction.h"
#include "core/skeleton/skeleton_input.h"
#include "core/skeleton/skeleton_json.h"

#include <QCommandLineParser>
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

struct SkeletonVerbOptions {
    std::string source;
    SkeletonOptions extraction;
    int loopLevels = 0;
    QString output; // .glb / .gltf, or empty
    QString json;   // or empty
};

void addSkeletonOptions(QCommandLineParser& parser)
{
    parser.setApplicationDescription(
        "Extracts an animation skeleton from a closed mesh by mesh contraction (Berenguer & Moreno): contraction, "
        "simplification, refinement and selection of about N joints; then bone-heat skinning weights, and exports "
        "the rigged mesh as glTF 2.0 and the skeleton as JSON. Prints the time of every stage as in the paper's "
        "Table III. See docs/skeleton.md.");
    parser.addPositionalArgument("mesh", "A closed, manifold, connected mesh (.obj .ply .stl .off .gltf .glb, "
                                         "optionally .gz) or demo:NAME.");
    parser.addOptions({
        {"nodes", "Joints of the rig (the selection's target node count, 2-10000). Default: 30.", "N"},
        {"ordering", "Fill-reducing ordering of the sparse factorizations: amd | colamd | metis. Default: metis.",
         "name"},
        {"solver", "Sparse Cholesky: cholmod (SuiteSparse) | ldlt (Eigen's SimplicialLDLT). Default: cholmod.",
         "name"},
        {"root", "Root joint index of the rig (0 to N-1). Default: chosen automatically.", "J"},
        {"loop-subdivide", "Loop-subdivide the mesh N times first (0-6; each level has 4x the faces). Default: 0.",
         "N"},
        {{"o", "output"}, "Write the rigged mesh: .glb (binary) or .gltf (embedded buffer).", "file"},
        {"json", "Write the skeleton (joints, tree, bones, vertex-joint map, curve skeleton) as JSON.", "file"},
    });
    parser.addHelpOption();
}

std::optional<QString> parseNumbers(const QCommandLineParser& parser, SkeletonVerbOptions& o)
{
    long long nodes = 30, root = -1, levels = 0;
    for (const auto& error : {parseIntegerFlag(parser, "nodes", 2, 10000, nodes), parseIntegerFlag(parser, "root", 0, 9999, root),
                              parseIntegerFlag(parser, "loop-subdivide", 0, 6, levels)}) {
        if (error)
            return error;
    }
    if (root >= nodes)
        return QStringLiteral("--root %1 is not one of the %2 joints (0 to %3)").arg(root).arg(nodes).arg(nodes - 1);
    o.extraction.targetNodes = int(nodes);
    o.extraction.rootJoint = int(root);
    o.loopLevels = int(levels);
    return std::nullopt;
}

std::optional<QString> parseSolver(const QCommandLineParser& parser, SkeletonVerbOptions& o)
{
    const QString ordering = parser.isSet("ordering") ? parser.value("ordering") : QStringLiteral("metis");
    if (ordering == "amd")
        o.extraction.contraction.ordering = SparseOrdering::Amd;
    else if (ordering == "colamd")
        o.extraction.contraction.ordering = SparseOrdering::Colamd;
    else if (ordering == "metis")
        o.extraction.contraction.ordering = SparseOrdering::Metis;
    else
        return QStringLiteral("unknown --ordering '%1' (use amd, colamd or metis)").arg(ordering);
    const QString solver = parser.isSet("solver") ? parser.value("solver") : QStringLiteral("cholmod");
    if (solver != "cholmod" && solver != "ldlt")
        return QStringLiteral("unknown --solver '%1' (use cholmod or ldlt)").arg(solver);
    o.extraction.contraction.backend = solver == "ldlt" ? SparseBackend::EigenSimplicialLdlt : SparseBackend::Cholmod;
    return std::nullopt;
}

std::optional<QString> parseOutputs(const QCommandLineParser& parser, SkeletonVerbOptions& o)
{
    o.output = parser.value("output");
    if (!o.output.isEmpty() && !o.output.endsWith(".glb", Qt::CaseInsensitive) &&
        !o.output.endsWith(".gltf", Qt::CaseInsensitive))
        return QStringLiteral("-o must name a .glb or .gltf file, got '%1'").arg(o.output);
    o.json = parser.value("json");
    if (parser.isSet("json") && o.json.isEmpty())
        return QStringLiteral("--json needs a file name");
    return checkOutputPaths({{"-o", o.output}, {"--json", o.json}});
}

std::variant<SkeletonVerbOptions, QString> parseSkeletonOptions(const QStringList& arguments, QString& help)
{
    QCommandLineParser parser;
    addSkeletonOptions(parser);
    if (!parser.parse(QStringList{QStringLiteral("trimlab skeleton")} + arguments))
        return parser.errorText();
    if (parser.isSet("help")) {
        help = verbHelpText(parser, QStringLiteral("skeleton"));
        return QString();
    }
    if (parser.positionalArguments().size() != 1)
        return QStringLiteral("skeleton needs exactly one mesh (a file or demo:NAME); see trimlab skeleton --help");
    SkeletonVerbOptions options;
    options.source = parser.positionalArguments().first().toStdString();
    for (const auto& error : {parseNumbers(parser, options), parseSolver(parser, options), parseOutputs(parser, options)}) {
        if (error)
            return *error;
    }
    return options;
}

// The mesh of a one-object source, in world coordinates.
TriangleMesh loadSingleMesh(const std::string& source)
{
    const LoadedScene loaded = loadScene(source);
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

// Everything the summary prints.
struct SkeletonRun {
    std::size_t inputVertices = 0, vertices = 0, faces = 0;
    double loadMs = 0.0, subdivisionMs = 0.0, weightsMs = 0.0, exportMs = 0.0, evaluationMs = 0.0;
    SkeletonExtraction extraction;
    SkeletonEvaluation curveQuality, rigQuality;
    BoneHeatReport weights;
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
                  .arg(seconds(r.evaluationMs)).arg(r.curveQuality.diagonal, 0, 'g', 4));
    for (const auto& [name, quality] : {std::pair{"curve", &r.curveQuality}, std::pair{"rig", &r.rigQuality}})
        for (const std::string& line : describeEvaluation(*quality))
            printLine(QStringLiteral("  %1 %2").arg(QString::fromLatin1(name), -5).arg(QString::fromStdString(line)));
}

void printSummary(const SkeletonVerbOptions& o, const SkeletonRun& r)
{
    QString mesh = QStringLiteral("%1: %2 vertices, %3 faces").arg(QString::fromStdString(o.source)).arg(r.vertices).arg(r.faces);
    if (o.loopLevels > 0)
        mesh += QStringLiteral(" (Loop-subdivided %1x from %2 vertices in %3 s)")
                    .arg(o.loopLevels).arg(r.inputVertices).arg(seconds(r.subdivisionMs));
    printLine(mesh + QStringLiteral("; loaded in %1 s").arg(seconds(r.loadMs)));
    const SkeletonRig& rig = r.extraction.rig;
    printLine(QStringLiteral("skeleton: %1 joints, %2 bones, root joint %3; curve skeleton %4 nodes, %5 edges")
                  .arg(rig.joints.size()).arg(rig.bones.size()).arg(rig.root).arg(r.extraction.curve.nodes.size())
                  .arg(r.extraction.curve.edges.size()));
    printLine(QStringLiteral("contraction: %1 iterations, %2 symbolic analysis(es), %3 numeric factorizations; %4")
                  .arg(r.extraction.contractionIterations).arg(r.extraction.symbolicAnalyses)
                  .arg(r.extraction.numericFactorizations).arg(QString::fromStdString(r.extraction.solver)));
    for (const std::string& warning : r.extraction.warnings)
        printNote(QString::fromStdString(warning));
    printLine(QStringLiteral("weights: %1; %2 vertices without a visible bone, %3 pinned to their nearest bone")
                  .arg(QString::fromStdString(r.weights.factorization)).arg(r.weights.hiddenVertices)
                  .arg(r.weights.pinnedVertices));
    if (!r.weights.note.empty())
        printNote(QString::fromStdString(r.weights.note));
    const SkeletonStageTimes& t = r.extraction.times;
    const double total = t.contractionMs + t.simplificationMs + t.refinementMs + t.selectionMs + r.weightsMs + r.exportMs;
    // The columns of the paper's Table III (times in seconds), each as wide as its name.
    const std::vector<std::pair<QString, QString>> columns = {
        {"vertices", QString::number(r.vertices)},
        {"iterations", QString::number(r.extraction.contractionIterations)},
        {"contraction", seconds(t.contractionMs)},
        {"simplification", seconds(t.simplificationMs)},
        {"refinement", seconds(t.refinementMs)},
        {"selection", seconds(t.selectionMs)},
        {"weights", seconds(r.weightsMs)},
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
SkeletonExtraction extract(const TriangleMesh& mesh, const SkeletonVerbOptions& o, const TaskControl& control)
{
    try {
        return extractSkeleton(mesh, o.extraction, control);
    } catch (const SkeletonInputError& e) {
        throw std::runtime_error(o.source + ": " + e.what());
    }
}

void exportResults(const TriangleMesh& mesh, const SkeletonVerbOptions& o, const SkeletonRun& r, const BoneWeights& w)
{
    if (!o.output.isEmpty())
        exportRiggedGltf(mesh, r.extraction.rig, w, o.output.toStdString());
    if (!o.json.isEmpty())
        saveSkeletonJson(o.json.toStdString(), r.extraction.rig, &r.extraction.curve);
}

int skeletonOfMesh(const SkeletonVerbOptions& o)
{
    const TaskControl control = terminalProgress();
    SkeletonRun run;
    QElapsedTimer timer;
    timer.start();
    TriangleMesh mesh = loadSingleMesh(o.source);
    run.loadMs = lapMilliseconds(timer);
    run.inputVertices = mesh.vertexCount();
    if (o.loopLevels > 0) {
        mesh = loopSubdivide(mesh, o.loopLevels);
        run.subdivisionMs = lapMilliseconds(timer);
    }
    run.vertices = mesh.vertexCount();
    run.faces = mesh.triangleCount();
    run.extraction = extract(mesh, o, control);
    timer.restart();
    {
        const SkeletonEvaluator evaluator(mesh);
        run.curveQuality = evaluator.evaluate(skeletonGraph(run.extraction.curve));
        run.rigQuality = evaluator.evaluate(skeletonGraph(run.extraction.rig));
    }
    run.evaluationMs = lapMilliseconds(timer);
    BoneHeatOptions heat;
    heat.backend = o.extraction.contraction.backend;
    heat.ordering = o.extraction.contraction.ordering;
    const BoneHeatSolver weights(mesh, run.extraction.rig, heat, control);
    run.weights = weights.report();
    run.weightsMs = lapMilliseconds(timer);
    exportResults(mesh, o, run, weights.weights());
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
    return runGuarded([&] { return skeletonOfMesh(std::get<SkeletonVerbOptions>(parsed)); });
}

} // namespace trimlab::app
