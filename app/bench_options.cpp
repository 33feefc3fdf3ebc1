#include "app/bench_options.h"

#include "app/output_paths.h"

#include "app/cli_messages.h"
#include "app/parameter_options.h"

#include "app/bench_scenes.h"
#include "app/bench_skinning.h"
#include "app/render_options.h"
#include "core/trim/static_rule.h"

#include <QCommandLineParser>
#include <QFileInfo>

#include <algorithm>
#include <optional>

namespace trimlab::app {

namespace {

QString catalogText()
{
    QStringList names;
    for (const std::string& name : benchSceneNames())
        names << QString::fromStdString(name);
    return names.join(QStringLiteral(", "));
}

void addBenchOptions(QCommandLineParser& parser)
{
    parser.setApplicationDescription(
        "Measures every multi-fragment method on a fixed camera path over named scenes and checks each frame "
        "against the exact CPU reference. Prints a table (and --json); exits 1 if a method disagrees with the "
        "reference beyond the render tests' threshold, never because of speed.");
    parser.addPositionalArgument("sources",
                                 "Optional mesh files or demo:NAME forming one more scene (object ids "
                                 "across them in order), drawn with --rule, --csg, --object-rule and "
                                 "--object-transform; alone unless --scenes is given.",
                                 "[SOURCE...]");
    parser.addOptions({
        {"scenes",
         QStringLiteral("Comma-separated scenes. Default: %1. Also any demo:NAME or mesh file, and the animation "
                        "scenes %2 (a skinned pose, CPU skinning + upload against GPU skinning).")
             .arg(catalogText(), QString::fromStdString(skinningBenchSceneNamesText())),
         "a,b"},
        {"size", "Comma-separated frame sizes. Default: 1024x768.", "WxH[,WxH]"},
        {"methods", QStringLiteral("Comma-separated methods. Default: all of %1.").arg(fragmentMethodIds().join(", ")),
         "a,b"},
        {"json", "Also write the results as JSON.", "file.json"},
        {"rule",
         QStringLiteral("Rule of the scene of the positional sources: %1, or none. Default: "
                        "alternating-border.")
             .arg(QString::fromStdString(staticRuleNamesHelp())),
         "rule"},
        {"csg", "CSG over the objects of the positional sources, as trimlab render --csg.", "expression"},
        {"object-rule", "Rule of one object of the positional sources, e.g. 1=parity. Repeatable.", "id=rule"},
        {"object-transform", objectTransformHelp(), "id=tx,ty,tz[,rx,ry,rz[,s]]"},
        {"data",
         "The shared data folder with the catalog's meshes. Default: $TRIMLAB_DATA_DIR or ../shared/data "
         "beside the source tree.",
         "dir"},
    });
    addParameterOptions(parser, bench_parameters::kTable);
    parser.addHelpOption();
}

std::optional<QString> parseSizes(const QString& text, BenchOptions& options)
{
    options.sizes.clear();
    for (const QString& item : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        int width = 0;
        int height = 0;
        if (auto e = parseImageSize(item.trimmed(), width, height))
            return e;
        options.sizes.emplace_back(width, height);
    }
    if (options.sizes.empty())
        return QStringLiteral("--size needs at least one WxH");
    return std::nullopt;
}

std::optional<QString> parseMethods(const QString& text, BenchOptions& options)
{
    std::vector<render::FragmentMethodKind> chosen;
    for (const QString& item : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const auto kind = render::parseFragmentMethod(item.trimmed().toStdString());
        if (!kind)
            return QStringLiteral("unknown method '%1' in --methods (this build has: %2)")
                .arg(item.trimmed(), fragmentMethodIds().join(QStringLiteral(", ")));
        chosen.push_back(*kind);
    }
    options.methods.clear();
    for (const render::MethodInfo& info : render::fragmentMethods()) // menu order, no duplicates
        if (std::find(chosen.begin(), chosen.end(), info.kind) != chosen.end())
            options.methods.push_back(info.kind);
    if (options.methods.empty())
        return QStringLiteral("--methods needs at least one method");
    return std::nullopt;
}

std::optional<QString> parseScenes(const QString& text, BenchOptions& options)
{
    for (const QString& item : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const QString name = item.trimmed();
        const bool known = isBenchSceneName(name.toStdString()) || isSkinningBenchScene(name.toStdString()) ||
                           name.startsWith(QStringLiteral("demo:")) || QFileInfo::exists(name);
        if (!known)
            return QStringLiteral("unknown scene '%1' in --scenes (use %2, demo:NAME or a mesh file)")
                .arg(name, catalogText());
        options.scenes << name;
    }
    if (options.scenes.isEmpty())
        return QStringLiteral("--scenes needs at least one scene");
    return std::nullopt;
}

// Every row of bench_parameters::kTable, before any other check.
std::optional<QString> parseParameters(const QCommandLineParser& parser, BenchOptions& options)
{
    using namespace bench_parameters;
    for (const std::optional<QString>& error :
         {parseParameter(parser, render::method_parameters::kK, options.parameters.k),
          parseParameter(parser, render::method_parameters::kSharedCounters, options.parameters.sharedCounters),
          parseParameter(parser, kRepeat, options.repeat), parseParameter(parser, kViews, options.views),
          parseParameter(parser, kThreads, options.threads), parseParameter(parser, kLocks, options.locks)}) {
        if (error)
            return error;
    }
    options.parameters.allowInterlock = options.locks != BenchLocks::SpinLock;
    return std::nullopt;
}

std::optional<QString> parseLists(const QCommandLineParser& parser, BenchOptions& options)
{
    if (parser.isSet("scenes"))
        if (auto e = parseScenes(parser.value("scenes"), options))
            return e;
    if (parser.isSet("size"))
        if (auto e = parseSizes(parser.value("size"), options))
            return e;
    for (const render::MethodInfo& info : render::fragmentMethods())
        options.methods.push_back(info.kind);
    if (parser.isSet("methods"))
        return parseMethods(parser.value("methods"), options);
    return std::nullopt;
}

// The positional sources and the options that draw their scene.
std::optional<QString> parseComposedScene(const QCommandLineParser& parser, BenchOptions& options)
{
    const QStringList positional = parser.positionalArguments();
    if (positional.isEmpty()) {
        for (const char* name : {"rule", "csg", "object-rule", "object-transform"})
            if (parser.isSet(name))
                return QStringLiteral("--%1 applies to the scene of the positional sources (trimlab bench A.obj B.obj "
                                      "--%1 ...); the --scenes keep their own settings")
                    .arg(QLatin1String(name));
        return std::nullopt;
    }
    if (auto e = takeSources(positional, QStringLiteral("bench"), options.sources))
        return e;
    TrimSettings& trim = options.composedTrim;
    trim.rule = StaticRule::AlternatingBorder;
    if (parser.isSet("rule"))
        if (auto e = parseRuleOption(parser.value("rule"), trim))
            return e;
    if (parser.isSet("csg"))
        if (auto e = parseCsgOption(parser.value("csg"), trim.csg))
            return e;
    for (const QString& text : parser.values("object-rule"))
        if (auto e = parseObjectRuleOption(text, trim.csg))
            return e;
    for (const QString& text : parser.values("object-transform"))
        if (auto e = parseObjectTransform(text, options.objectTransforms))
            return e;
    if (trim.csg.enabled() && !trim.trimEnabled)
        return QStringLiteral("--rule none has no interior: --csg needs a rule");
    return std::nullopt;
}

} // namespace

std::variant<BenchOptions, QString> parseBenchOptions(const QStringList& arguments, QString* helpText)
{
    QCommandLineParser parser;
    addBenchOptions(parser);
    if (!parser.parse(QStringList{QStringLiteral("trimlab bench")} + arguments))
        return parser.errorText();
    if (parser.isSet("help")) {
        if (helpText)
            *helpText = verbHelpText(parser, QStringLiteral("bench"));
        return QString();
    }
    BenchOptions options;
    if (auto e = parseParameters(parser, options))
        return *e;
    if (auto e = parseComposedScene(parser, options))
        return *e;
    options.jsonOutput = parser.value("json");
    if (auto e = checkOutputPaths({{"--json", options.jsonOutput}}))
        return *e;
    options.dataDirectory = parser.value("data");
    if (auto e = parseLists(parser, options))
        return *e;
    return options;
}

} // namespace trimlab::app
