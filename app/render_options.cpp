#include "app/render_options.h"

#include "app/output_paths.h"

#include "app/cli_messages.h"
#include "app/parameter_options.h"
#include "app/scene_composition.h"

#include "render/mfr/fragment_method.h"
#include "core/catalog/scene_source.h"
#include "core/catalog/surface_scenes.h"
#include "core/timeline/project_file.h"
#include "core/trim/clip_plane.h"
#include "core/trim/clip_set.h"
#include "core/trim/csg_expression.h"

#include <QCommandLineParser>
#include <QRegularExpression>

#include <algorithm>

namespace trimlab::app {

namespace {

void addRenderOptions(QCommandLineParser& parser)
{
    parser.setApplicationDescription(
        "Renders mesh files or built-in demos (demo:pushed-sphere, demo:crossing-loop, ...) trimmed by a static rule, "
        "or a frame of a design (a stroke script replayed on the mesh, or a .trimlab project) under the dynamic "
        "rules.");
    parser.addPositionalArgument("sources",
                                 "One or more mesh files (.obj .ply .stl .off .gltf .glb, optionally .gz) "
                                 "or demo:NAME, one scene whose object ids count across them in order; or "
                                 "one .trimlab project.",
                                 "SOURCE...");
    parser.addOptions({
        {"rule",
         "parity | positive-index | alternating-border | nonzero | negative | 'w>=K' | '|w|>=K' (quoted; "
         "or at-least-K, abs-at-least-K) | none (no trimming). Default: alternating-border.",
         "rule"},
        {"clip",
         QStringLiteral("Clipping plane a,b,c,d keeping a*x+b*y+c*z+d >= 0 (world space). Repeat for up to %1 "
                        "planes (e.g. a clipping box); together they keep the points every plane keeps.")
             .arg(kMaxClipPlanes),
         "a,b,c,d"},
        {"cap", "Cap the cut: where a clipping plane cuts into the solid (under the rule, or the CSG result), show "
                "the plane there, lit flat and cross-hatched in world space. Needs --clip."},
        {"cap-pattern", "Pattern of the caps: hatched, striped or solid. Default: hatched.", "name"},
        {"csg",
         QStringLiteral("CSG of the scene's objects (ids 0-%1 in source order): | union, & intersection, - "
                        "difference, parentheses, e.g. \"0 | (1 & 2)\" or \"(0 | 1) - 2\". Each object is "
                        "classified by its own rule (--object-rule, else --rule). Buffer methods only.")
             .arg(kMaxCsgOperands - 1),
         "expression"},
        {"object-rule", "Rule of one object for --csg and collision highlighting, e.g. 0=parity. Repeatable.",
         "id=rule"},
        {"object-transform", objectTransformHelp(), "id=tx,ty,tz[,rx,ry,rz[,s]]"},
        {"highlight",
         "Tint shown fragments: collisions (inside another object, or where an object overlaps "
         "itself) and/or coplanar (groups of fragments at equal depth, by group size); comma-separated. "
         "Buffer methods only.",
         "what"},
        {"transparency",
         "X-ray over the kept span's sorted fragments: opaque (the trimmed solid as usual, the "
         "fragments the trim removed in front of it as translucent ghosts) or translucent (every "
         "boundary of the trimmed solid, caps included, as a translucent layer). Buffer methods only.",
         "mode"},
        {"method",
         QStringLiteral("Multi-fragment method of the OpenGL backend: %1. Default: kplus-array.")
             .arg(fragmentMethodIds().join(QStringLiteral(", "))),
         "id"},
        {"size", "Image size. Default: 1024x768.", "WxH"},
        {"camera", "Eye, target, up and vertical field of view in degrees. Default: fitted to the scene.",
         "ex,ey,ez,tx,ty,tz,ux,uy,uz,fovy"},
        {"backend", "kplus (OpenGL, the method of --method) or reference (exact CPU ray caster). Default: kplus.",
         "name"},
        {{"o", "output"}, "Output PNG (required).", "file.png"},
        {"depth", "Also write the shown surface's distance along each view ray as a PFM (empty pixels +inf).",
         "file.pfm"},
        {"ids", "Also write object and primitive ids as a 16-bit RGBA PNG (see docs/file-formats.md).", "file.png"},
        {"script",
         "Replay this stroke script (docs/project-format.md) on the source mesh and render one of its "
         "frames.",
         "strokes.json"},
        {"classification",
         "For a script or project: dynamic (each set's rule, the base mesh classified by --rule) "
         "or static (--rule on the frame alone). Default: dynamic.",
         "name"},
        {"pose",
         "The source is a mesh animation (a folder or numbered pattern of meshes such as 'walk_%04d.obj', or "
         "a glTF file): render its pose N (0 = the first).",
         "N"},
        {"poses",
         "The source is a mesh animation: render poses A to B, one image each, with one camera for all; "
         "-o (and --depth, --ids) hold the pose number as %d or %04d, e.g. frame_%04d.png.",
         "A:B"},
        {"dynamic-rule",
         "With --pose/--poses: classify each pose by this dynamic rule against --reference, the "
         "animation being the deformation history (additive, subtractive, intersection, confluent, "
         "homogeneous-confluent); the rest pose is classified by --rule. Default: --rule on each pose "
         "alone.",
         "name"},
        {"reference",
         "With --dynamic-rule: rest (each pose against the rest pose) or previous (the classification "
         "carries from pose to pose, from the rest pose on). Default: rest.",
         "name"},
        {"sets",
         "With --pose/--poses, instead of --dynamic-rule: the poses after the rest pose as sets of "
         "consecutive poses, each from its first pose to the next set's, with its own dynamic rule, e.g. "
         "1:confluent,40:additive; a set's reference is the pose before its first.",
         "A:rule,..."},
    });
    addParameterOptions(parser, render_verb_parameters::kTable);
    parser.addHelpOption();
}

// Every row of render_verb_parameters::kTable, before any other check.
std::optional<QString> parseParameters(const QCommandLineParser& parser, RenderOptions& options)
{
    using namespace render::method_parameters;
    using namespace render_verb_parameters;
    TransparencySettings& xray = options.trim.transparency;
    int budget = int(kMemoryBudget.defaultValue);
    int frame = 0;
    for (const std::optional<QString>& error :
         {parseParameter(parser, kK, options.parameters.k),
          parseParameter(parser, kSharedCounters, options.parameters.sharedCounters),
          parseParameter(parser, kMemoryBudget, budget),
          parseParameter(parser, inspect_parameters::kLayerAlpha, xray.layerAlpha),
          parseParameter(parser, inspect_parameters::kGhostAlpha, xray.ghostAlpha),
          parseParameter(parser, inspect_parameters::kDensity, xray.density),
          parseParameter(parser, inspect_parameters::kFresnel, xray.fresnelExponent),
          parseParameter(parser, inspect_parameters::kCapSpacing, options.capSpacingFraction),
          parseParameter(parser, kRepeat, options.repeat), parseParameter(parser, kThreads, options.threads),
          parseParameter(parser, kFrame, frame),
          parseParameter(parser, hole_closing_parameters::kCloseHoles, options.closeHoles)}) {
        if (error)
            return error;
    }
    options.parameters.memoryBudgetBytes = budgetBytes(budget);
    if (parser.isSet(QStringLiteral("frame")))
        options.frame = frame;
    return std::nullopt;
}

std::optional<QString> parseRule(const QString& text, RenderOptions& options)
{
    options.ruleGiven = true;
    return parseRuleOption(text, options.trim);
}

std::optional<QString> parseGeometryOptions(const QCommandLineParser& parser, RenderOptions& options)
{
    if (std::optional<QString> clipError = parseClipOptions(parser, options.trim))
        return clipError;
    std::string error;
    if (parser.isSet("camera")) {
        options.camera = parseCamera(parser.value("camera").toStdString(), &error);
        if (!options.camera)
            return QStringLiteral("--camera: ") + QString::fromStdString(error);
    }
    return std::nullopt;
}

std::optional<QString> parseMethodOptions(const QCommandLineParser& parser, RenderOptions& options)
{
    if (parser.isSet("method")) {
        const QString id = parser.value("method");
        const auto method = render::parseFragmentMethod(id.toStdString());
        if (!method)
            return QStringLiteral("unknown --method '%1' (this build has: %2)")
                .arg(id, fragmentMethodIds().join(QStringLiteral(", ")));
        options.method = *method;
    }
    return std::nullopt;
}

std::optional<QString> parseDesignOptions(const QCommandLineParser& parser, RenderOptions& options)
{
    options.script = parser.value("script");
    if (options.sources.size() > 1 &&
        (!options.script.isEmpty() || std::any_of(options.sources.begin(), options.sources.end(), isDesignSource)))
        return QStringLiteral("--script, .trimlab projects and demos with a history take exactly one source; several "
                              "sources make a scene of meshes");
    if (options.designed() && !options.objectTransforms.empty())
        return QStringLiteral("--object-transform places the objects of mesh sources; a design keeps its own "
                              "placement");
    if (options.designed() && options.closeHoles)
        return QStringLiteral("--close-holes closes mesh sources and animations; a design's base mesh is closed "
                              "already (a design starts only on a closed mesh)");
    const QString classification = parser.value("classification");
    options.classificationGiven = parser.isSet("classification");
    if (classification == QLatin1String("static"))
        options.classification = Classification::Static;
    else if (!classification.isEmpty() && classification != QLatin1String("dynamic"))
        return QStringLiteral("unknown --classification '%1' (use dynamic or static)").arg(classification);
    if ((options.frame || parser.isSet("classification")) && !options.designed())
        return QStringLiteral("--frame and --classification need --script, a .trimlab project source or a "
                              "demo with a history (demo:nurbs-fig8-13, demo:subdivision-push)");
    const TrimSettings& trim = options.trim;
    if (options.designed() && options.classification == Classification::Dynamic &&
        (trim.cap.enabled || trim.csg.enabled() || trim.highlight.any() || trim.xray()))
        return QStringLiteral("--cap, --csg, --highlight and --transparency need static classification of a design "
                              "(--classification static)");
    if (options.designed() && !options.trim.trimEnabled && options.classification == Classification::Dynamic)
        return QStringLiteral("--rule none cannot classify the base mesh of the dynamic rules; use --classification "
                              "static to render without trimming");
    return std::nullopt;
}

// --pose / --poses: one animation source, one object, an output name per pose.
std::optional<QString> parsePoseOptions(const QCommandLineParser& parser, RenderOptions& options)
{
    if (auto e = parsePoseSelection(parser.value("pose"), parser.value("poses"), options.poses))
        return e;
    if (!options.poses) {
        if (parser.isSet("dynamic-rule") || parser.isSet("reference") || parser.isSet("sets"))
            return QStringLiteral("--dynamic-rule, --reference and --sets classify the poses of an animation: give "
                                  "--pose N or --poses A:B");
        return std::nullopt;
    }
    if (parser.isSet("dynamic-rule")) {
        options.poseRule = parseDynamicRule(parser.value("dynamic-rule").toStdString());
        if (!options.poseRule)
            return QStringLiteral("unknown --dynamic-rule '%1' (use additive, subtractive, intersection, confluent or "
                                  "homogeneous-confluent)")
                .arg(parser.value("dynamic-rule"));
    }
    if (parser.isSet("reference")) {
        const std::optional<PoseReference> reference = parsePoseReference(parser.value("reference").toStdString());
        if (!reference)
            return QStringLiteral("unknown --reference '%1' (use rest or previous)").arg(parser.value("reference"));
        if (!options.poseRule)
            return QStringLiteral("--reference is the reference of --dynamic-rule; give a dynamic rule too");
        options.poseReference = *reference;
    }
    if (parser.isSet("sets")) {
        if (options.poseRule)
            return QStringLiteral("--sets gives every set its rule; leave out --dynamic-rule and --reference");
        std::string error;
        options.poseSets = parsePoseSets(parser.value("sets").toStdString(), error);
        if (!options.poseSets)
            return QStringLiteral("--sets: %1").arg(QString::fromStdString(error));
        options.poseRule = options.poseSets->front().rule;
    }
    const TrimSettings& trim = options.trim;
    if (options.poseRule && (trim.cap.enabled || trim.highlight.any() || trim.xray() || !trim.trimEnabled))
        return QStringLiteral("--dynamic-rule classifies the trimmed solid itself: --cap, --highlight, --transparency "
                              "and --rule none are for static rules");
    if (options.sources.size() != 1 || options.designed())
        return QStringLiteral("--pose and --poses render one mesh animation source (a folder, a numbered pattern or "
                              "a glTF file), not several sources, a script or a project");
    if (options.trim.csg.enabled() || !options.objectTransforms.empty())
        return QStringLiteral("--csg and --object-transform combine several objects; an animation is one object");
    if (!options.poses->sequence)
        return std::nullopt;
    for (const auto& [option, path] : {std::pair{"-o", options.output}, std::pair{"--depth", options.depthOutput},
                                       std::pair{"--ids", options.idsOutput}})
        if (!path.isEmpty() && !hasPoseNumber(path))
            return QStringLiteral("--poses writes one file per pose: %1 '%2' needs the pose number in its name as "
                                  "%d or %04d (e.g. frame_%04d.png)")
                .arg(QLatin1String(option), path);
    return std::nullopt;
}

// --cap, --csg, --object-rule, --highlight (after --rule and --clip are known).
std::optional<QString> parseInspectionOptions(const QCommandLineParser& parser, RenderOptions& options)
{
    options.trim.cap.enabled = parser.isSet("cap");
    if (options.trim.cap.enabled && !options.trim.clipSet().anyEnabled())
        return QStringLiteral("--cap needs at least one --clip plane to cut with");
    if (parser.isSet("cap-spacing") && !options.trim.cap.enabled)
        return QStringLiteral("--cap-spacing is the spacing of the cap's pattern; give --cap too");
    if (parser.isSet("cap-pattern")) {
        const std::optional<CapPattern> pattern = parseCapPattern(parser.value("cap-pattern").toStdString());
        if (!pattern)
            return QStringLiteral("unknown --cap-pattern '%1' (use hatched, striped or solid)")
                .arg(parser.value("cap-pattern"));
        options.trim.cap.pattern = *pattern;
    }
    if (parser.isSet("csg"))
        if (auto e = parseCsgOption(parser.value("csg"), options.trim.csg))
            return e;
    for (const QString& text : parser.values("object-rule"))
        if (auto e = parseObjectRuleOption(text, options.trim.csg))
            return e;
    for (const QString& text : parser.values("object-transform"))
        if (auto e = parseObjectTransform(text, options.objectTransforms))
            return e;
    for (const QString& value : parser.values("highlight")) {
        for (const QString& what : value.split(QLatin1Char(','))) {
            if (what == QLatin1String("collisions"))
                options.trim.highlight.collisions = true;
            else if (what == QLatin1String("coplanar"))
                options.trim.highlight.coplanar = true;
            else
                return QStringLiteral("unknown --highlight '%1' (use collisions or coplanar)").arg(what);
        }
    }
    const bool needsRule = options.trim.cap.enabled || options.trim.csg.enabled() || options.trim.highlight.collisions;
    if (needsRule && !options.trim.trimEnabled)
        return QStringLiteral("--rule none has no interior: --cap, --csg and --highlight collisions need a rule");
    return std::nullopt;
}

// --transparency and the values it uses.
std::optional<QString> parseTransparencyOptions(const QCommandLineParser& parser, RenderOptions& options)
{
    TransparencySettings& xray = options.trim.transparency;
    if (parser.isSet("transparency")) {
        const std::optional<TrimDisplay> display = parseTrimDisplay(parser.value("transparency").toStdString());
        if (!display)
            return QStringLiteral("unknown --transparency '%1' (use opaque or translucent)")
                .arg(parser.value("transparency"));
        xray.enabled = true;
        xray.display = *display;
    }
    for (const char* name : {"layer-alpha", "ghost-alpha", "density", "fresnel"})
        if (parser.isSet(name) && !xray.enabled)
            return QStringLiteral("--%1 needs --transparency opaque|translucent").arg(QLatin1String(name));
    return std::nullopt;
}

std::optional<QString> parseBackendOptions(const QCommandLineParser& parser, RenderOptions& options)
{
    if (parser.isSet("size"))
        if (auto e = parseImageSize(parser.value("size"), options.width, options.height))
            return e;
    const QString backend = parser.value("backend");
    if (backend == QLatin1String("reference"))
        options.backend = Backend::Reference;
    else if (!backend.isEmpty() && backend != QLatin1String("kplus"))
        return QStringLiteral("unknown --backend '%1' (use kplus or reference)").arg(backend);
    return std::nullopt;
}

} // namespace

std::optional<QString> parseImageSize(const QString& text, int& width, int& height)
{
    static const QRegularExpression pattern(QStringLiteral(R"(^(\d{1,5})x(\d{1,5})$)"));
    const QRegularExpressionMatch m = pattern.match(text);
    if (!m.hasMatch())
        return QStringLiteral("--size must look like 1024x768, got '%1'").arg(text);
    width = m.captured(1).toInt();
    height = m.captured(2).toInt();
    if (width < 1 || height < 1 || width > 16384 || height > 16384)
        return QStringLiteral("--size must be between 1x1 and 16384x16384, got '%1'").arg(text);
    return std::nullopt;
}

QStringList fragmentMethodIds()
{
    QStringList ids;
    for (const render::MethodInfo& info : render::fragmentMethods())
        ids << QString::fromLatin1(info.id.data(), qsizetype(info.id.size()));
    return ids;
}

std::variant<RenderOptions, QString> parseRenderOptions(const QStringList& arguments, QString* helpText)
{
    QCommandLineParser parser;
    addRenderOptions(parser);
    if (!parser.parse(QStringList{QStringLiteral("trimlab render")} + arguments))
        return parser.errorText();
    if (parser.isSet("help")) {
        if (helpText)
            *helpText = verbHelpText(parser, QStringLiteral("render"));
        return QString();
    }
    RenderOptions options;
    if (auto e = parseParameters(parser, options))
        return *e;
    if (auto e = takeSources(parser.positionalArguments(), QStringLiteral("render"), options.sources))
        return *e;
    options.designSource = options.sources.size() == 1 && isDesignSource(options.sources.front());
    if (!parser.isSet("output"))
        return QStringLiteral("render needs an output image: -o out.png");
    options.output = parser.value("output");
    options.depthOutput = parser.value("depth");
    options.idsOutput = parser.value("ids");
    if (auto e =
            checkOutputPaths({{"-o", options.output}, {"--depth", options.depthOutput}, {"--ids", options.idsOutput}}))
        return *e;
    if (parser.isSet("rule"))
        if (auto e = parseRule(parser.value("rule"), options))
            return *e;
    if (auto e = parseGeometryOptions(parser, options))
        return *e;
    if (auto e = parseInspectionOptions(parser, options))
        return *e;
    if (auto e = parseTransparencyOptions(parser, options))
        return *e;
    if (auto e = parseBackendOptions(parser, options))
        return *e;
    if (auto e = parseMethodOptions(parser, options))
        return *e;
    if (auto e = parseDesignOptions(parser, options))
        return *e;
    if (auto e = parsePoseOptions(parser, options))
        return *e;
    const render::MethodInfo& method = render::methodInfo(options.method);
    const bool needsWalk = options.trim.perObjectWinding() || options.trim.highlight.coplanar;
    if (options.backend == Backend::KPlus && needsWalk && !method.inspection)
        return QStringLiteral("--method %1 cannot render --csg or --highlight (it never holds all of a pixel's "
                              "fragments at once); use a buffer method such as kplus-array or abuffer-linked-list")
            .arg(QString::fromLatin1(method.id.data(), qsizetype(method.id.size())));
    if (options.backend == Backend::KPlus && options.trim.xray() && !method.inspection)
        return QStringLiteral("--method %1 cannot render --transparency (it never holds all of a pixel's fragments "
                              "at once); use a buffer method such as kplus-array or abuffer-linked-list")
            .arg(QString::fromLatin1(method.id.data(), qsizetype(method.id.size())));
    return options;
}

bool isDesignSource(const std::string& source)
{
    // A scene project (several objects, no history) renders like any other scene.
    if (QString::fromStdString(source).endsWith(QLatin1String(".trimlab"), Qt::CaseInsensitive))
        return !timeline::isSceneProject(source);
    return isDemoSource(source) && hasSurfaceDemoHistory(std::string_view(source).substr(kDemoPrefix.size()));
}

bool RenderOptions::designed() const
{
    return !script.isEmpty() || designSource;
}

} // namespace trimlab::app
