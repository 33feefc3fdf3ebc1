#include "render_options.h"

#include "mfr/kplus_buffer.h"
#include "mfr/fragment_method.h"
#include "trim/clip_plane.h"

#include <QCommandLineParser>
#include <QRegularExpression>

namespace trimlab::app {

namespace {

void addRenderOptions(QCommandLineParser& parser)
{
    parser.setApplicationDescription(
        "Renders a mesh file or a built-in demo (demo:pushed-sphere, demo:crossing-loop, ...) trimmed by a static rule.");
    parser.addPositionalArgument("source", "A mesh file (.obj .ply .stl .off .gltf .glb, optionally .gz) or demo:NAME.");
    parser.addOptions({
        {"rule", "parity | positive-index | alternating-border | none (no trimming). Default: alternating-border.", "rule"},
        {"clip", "Clipping plane a,b,c,d keeping a*x+b*y+c*z+d >= 0 (world space).", "a,b,c,d"},
        {"k", "Fragments kept per pixel by the k+-buffer (1-128). Default: 16.", "N"},
        {"size", "Image size. Default: 1024x768.", "WxH"},
        {"camera", "Eye, target, up and vertical field of view in degrees. Default: fitted to the scene.",
         "ex,ey,ez,tx,ty,tz,ux,uy,uz,fovy"},
        {"backend", "kplus (OpenGL k+-buffer) or reference (exact CPU ray caster). Default: kplus.", "name"},
        {"threads", "Worker threads of the reference backend (0 = all cores).", "N"},
        {"repeat", "Render N times and report the median time (the first frame includes shader JIT). Default: 1.", "N"},
        {{"o", "output"}, "Output PNG (required).", "file.png"},
        {"depth", "Also write the shown surface's distance along each view ray as a PFM (empty pixels +inf).", "file.pfm"},
        {"ids", "Also write object and primitive ids as a 16-bit RGBA PNG (see docs/file-formats.md).", "file.png"},
    });
    parser.addHelpOption();
}

std::optional<QString> parseSize(const QString& text, RenderOptions& options)
{
    static const QRegularExpression pattern(QStringLiteral(R"(^(\d{1,5})x(\d{1,5})$)"));
    const QRegularExpressionMatch m = pattern.match(text);
    if (!m.hasMatch())
        return QStringLiteral("--size must look like 1024x768, got '%1'").arg(text);
    options.width = m.captured(1).toInt();
    options.height = m.captured(2).toInt();
    if (options.width < 1 || options.height < 1 || options.width > 16384 || options.height > 16384)
        return QStringLiteral("--size must be between 1x1 and 16384x16384, got '%1'").arg(text);
    return std::nullopt;
}

std::optional<QString> parseRule(const QString& text, RenderOptions& options)
{
    options.ruleGiven = true;
    if (text == QLatin1String("none")) {
        options.trim.trimEnabled = false;
        return std::nullopt;
    }
    const std::optional<StaticRule> rule = parseStaticRule(text.toStdString());
    if (!rule)
        return QStringLiteral("unknown --rule '%1' (use parity, positive-index, alternating-border or none)").arg(text);
    options.trim.rule = *rule;
    return std::nullopt;
}

std::optional<QString> parseIntOption(const QString& name, const QString& text, int lo, int hi, int& out)
{
    bool ok = false;
    out = text.toInt(&ok);
    if (!ok || out < lo || out > hi)
        return QStringLiteral("--%1 must be an integer from %2 to %3, got '%4'").arg(name).arg(lo).arg(hi).arg(text);
    return std::nullopt;
}

std::optional<QString> parseGeometryOptions(const QCommandLineParser& parser, RenderOptions& options)
{
    std::string error;
    if (parser.isSet("clip")) {
        const std::optional<ClipPlane> plane = parseClipPlane(parser.value("clip").toStdString(), &error);
        if (!plane)
            return QStringLiteral("--clip: ") + QString::fromStdString(error);
        options.trim.clip = *plane;
    }
    if (parser.isSet("camera")) {
        options.camera = parseCamera(parser.value("camera").toStdString(), &error);
        if (!options.camera)
            return QStringLiteral("--camera: ") + QString::fromStdString(error);
    }
    return std::nullopt;
}

std::optional<QString> parseBackendOptions(const QCommandLineParser& parser, RenderOptions& options)
{
    if (parser.isSet("size"))
        if (auto e = parseSize(parser.value("size"), options))
            return e;
    if (parser.isSet("k"))
        if (auto e = parseIntOption("k", parser.value("k"), 1, render::MethodParameters::kMaxK, options.k))
            return e;
    if (parser.isSet("repeat"))
        if (auto e = parseIntOption("repeat", parser.value("repeat"), 1, 1000, options.repeat))
            return e;
    if (parser.isSet("threads")) {
        int threads = 0;
        if (auto e = parseIntOption("threads", parser.value("threads"), 0, 1024, threads))
            return e;
        options.threads = unsigned(threads);
    }
    const QString backend = parser.value("backend");
    if (backend == QLatin1String("reference"))
        options.backend = Backend::Reference;
    else if (!backend.isEmpty() && backend != QLatin1String("kplus"))
        return QStringLiteral("unknown --backend '%1' (use kplus or reference)").arg(backend);
    return std::nullopt;
}

} // namespace

std::variant<RenderOptions, QString> parseRenderOptions(const QStringList& arguments, QString* helpText)
{
    QCommandLineParser parser;
    addRenderOptions(parser);
    if (!parser.parse(QStringList{QStringLiteral("trimlab render")} + arguments))
        return parser.errorText();
    if (parser.isSet("help")) {
        if (helpText)
            *helpText = parser.helpText();
        return QString();
    }
    RenderOptions options;
    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 1)
        return QStringLiteral("render needs exactly one source (a mesh file or demo:NAME); see trimlab render --help");
    options.source = positional.first().toStdString();
    if (!parser.isSet("output"))
        return QStringLiteral("render needs an output image: -o out.png");
    options.output = parser.value("output");
    options.depthOutput = parser.value("depth");
    options.idsOutput = parser.value("ids");
    if (parser.isSet("rule"))
        if (auto e = parseRule(parser.value("rule"), options))
            return *e;
    if (auto e = parseGeometryOptions(parser, options))
        return *e;
    if (auto e = parseBackendOptions(parser, options))
        return *e;
    return options;
}

} // namespace trimlab::app
