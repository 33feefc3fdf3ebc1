// The agreement of the animation rules with the reference, measured: every pose of mesh
// animations rendered on the GPU under a static rule and under two dynamic rules against
// the previous pose, on every method that runs the dynamic rules (the buffer methods), each
// frame compared with the exact CPU reference by the render tests' criteria
// (method_check.h: >= 99.9 % of compared pixels, <= 5 % excluded, bounded methods compared
// where they report no overflow). The dynamic frames are played as the Timeline plays them,
// one set appended per pose (DynamicTrimRenderer::appendLevel); their reference carries
// each pixel's characterization from pose to pose the same way
// (core/trim/dynamic_reference_sequence.h), which equals DynamicReferenceRenderer over the
// pose's whole chain (core.dynamic_rules). One camera fitted to all poses; a clip plane
// through each pose's centre, facing the camera, so that the interiors the rules decide are
// seen. Not a test: prints a table, exits 1 when a frame fails the criteria.
//
//   xvfb-run -a build/tests/render/bench_animation_agreement [--size WxH] [--step N] [ANIMATION...]
//   (default: ../shared/data/anim/samba and ../shared/data/anim/horse-gallop, closed by fans;
//    320x240, every pose)
#include "gl_test_context.h"
#include "method_check.h"
#include "test_paths.h"

#include "render/dynamic_trim_renderer.h"
#include "render/gl/offscreen_gl_context.h"
#include "render/trim_renderer.h"

#include "core/animation/animation_loader.h"
#include "core/animation/closed_animation.h"
#include "core/trim/dynamic_reference_sequence.h"
#include "core/view/camera.h"

#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QGuiApplication>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

using namespace trimlab;

namespace {

struct Mode {
    std::string name;
    std::optional<DynamicRule> rule; ///< nullopt: the static rule alone
};

const std::vector<Mode>& modes()
{
    static const std::vector<Mode> all{{"alternating border (static)", std::nullopt},
                                       {"confluent / previous", DynamicRule::Confluent},
                                       {"additive / previous", DynamicRule::ConstructiveAdditive}};
    return all;
}

// One method's renderers: a TrimRenderer of its own (so that the dynamic renderer's cache
// survives the other methods' frames) and its dynamic renderer.
struct MethodRun {
    render::FragmentMethodKind kind;
    std::string id;
    std::unique_ptr<render::TrimRenderer> renderer;
    std::unique_ptr<render::DynamicTrimRenderer> dynamic;
    int frames = 0;
    int failing = 0;
    int overflowed = 0; ///< frames with pixels the method flagged as overflowed
    long compared = 0;  ///< pixels compared, over the frames
    int sparse = 0;     ///< frames comparing fewer than 1 % of the pixels
    double worst = 1.0;
    double sum = 0.0;
    double milliseconds = 0.0;
};

struct Options {
    int width = 320;
    int height = 240;
    std::size_t step = 1;
    std::vector<std::string> animations;
};

Camera cameraFor(const MeshAnimation& animation, double aspect)
{
    Bounds bounds;
    for (const std::vector<glm::vec3>& pose : animation.poses)
        for (const glm::vec3& p : pose)
            bounds.extend(glm::dvec3(p));
    return withDepthRange(fitCamera(bounds, aspect), bounds);
}

// The plane through the centre of the pose's bounding box, facing the camera, whose kept
// side is the far half (a character that travels leaves the centre of the frame).
ClipPlane centreCut(const Camera& camera, const std::vector<glm::vec3>& pose)
{
    Bounds bounds;
    for (const glm::vec3& p : pose)
        bounds.extend(glm::dvec3(p));
    const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
    return ClipPlane{true, forward, -glm::dot(forward, bounds.center())};
}

Scene poseScene(const MeshAnimation& animation, std::size_t pose)
{
    Scene scene;
    scene.objects.push_back({"pose", TriangleMesh{animation.poses[pose], animation.triangles}, glm::dmat4(1.0)});
    return scene;
}

// "(N of M compared pixels": N.
long comparedOf(const QString& summary)
{
    const qsizetype open = summary.indexOf(QLatin1Char('('));
    return open < 0 ? 0 : summary.mid(open + 1, summary.indexOf(QLatin1Char(' '), open) - open - 1).toLong();
}

double agreementOf(const QString& summary)
{
    const qsizetype at = summary.indexOf(QStringLiteral("agreement "));
    return at < 0 ? 0.0
                  : summary.mid(at + 10, summary.indexOf(QLatin1Char('%'), at) - at - 10).trimmed().toDouble() / 100.0;
}

void record(MethodRun& run, const test::MethodCase& testCase, const ReferenceResult& reference, double ms,
            const char* animation, const Mode& mode, std::size_t pose)
{
    // A dancer or a horse covers a few percent of a frame fitted to all of its poses and
    // cut in half, and under a constructive rule less and less: the render tests' floor
    // against vacuous cases is no criterion here. Frames comparing fewer than 1 % of
    // the pixels are counted apart ("sparse") and the pixels compared are printed.
    test::MethodCriteria criteria;
    criteria.minimumCoverage = 0.0;
    QString summary;
    const std::optional<QString> failure =
        test::checkFrameAgainstReference(*run.renderer, testCase, reference, {}, &summary, criteria);
    const long compared = comparedOf(summary);
    run.compared += compared;
    if (compared < long(testCase.width) * testCase.height / 100)
        ++run.sparse;
    const double agreement = agreementOf(summary);
    ++run.frames;
    run.sum += agreement;
    run.worst = std::min(run.worst, agreement);
    run.milliseconds += ms;
    if (run.renderer->lastStats().counts.overflowPixels > 0)
        ++run.overflowed;
    if (failure) {
        ++run.failing;
        std::fprintf(stderr, "%s, %s, %s, pose %zu: %s\n", animation, mode.name.c_str(), run.id.c_str(), pose,
                     qPrintable(*failure));
    }
}

bool measureAnimation(const std::string& source, const Options& options, QOpenGLContext& context)
{
    MeshAnimation animation = closeAnimationHoles(loadAnimation(source));
    const std::string name = std::filesystem::path(source).filename().string();
    const Camera camera = cameraFor(animation, double(options.width) / options.height);
    TrimSettings settings;
    settings.rule = StaticRule::AlternatingBorder;
    render::MethodParameters parameters;
    parameters.k = 32;
    bool allPass = true;
    for (const Mode& mode : modes()) {
        std::vector<MethodRun> runs;
        for (const render::MethodInfo& info : render::fragmentMethods())
            if (info.dynamicRules) {
                MethodRun run{info.kind, std::string(info.id), std::make_unique<render::TrimRenderer>(context),
                              nullptr};
                run.renderer->setMethod(info.kind);
                run.renderer->setParameters(parameters);
                if (mode.rule)
                    run.dynamic = std::make_unique<render::DynamicTrimRenderer>(*run.renderer);
                runs.push_back(std::move(run));
            }
        DynamicReferenceSequence sequence(camera, options.width, options.height, settings.rule);
        QElapsedTimer referenceClock;
        double referenceMs = 0.0;
        std::size_t previous = animation.restPose;
        for (std::size_t pose = animation.restPose + 1; pose < animation.poseCount(); pose += options.step) {
            settings.clip = centreCut(camera, animation.poses[pose]); // the characterizations ignore it
            const test::MethodCase testCase{
                QStringLiteral("%1-%2-pose-%3")
                    .arg(QString::fromStdString(name))
                    .arg(mode.rule ? QString::fromLatin1(dynamicRuleName(*mode.rule).data()) : QStringLiteral("static"))
                    .arg(pose),
                camera,
                settings,
                parameters,
                options.width,
                options.height};
            referenceClock.start();
            std::optional<DynamicChainLevel> level;
            ReferenceResult reference;
            if (mode.rule) {
                // With --step > 1 a set spans several poses: its reference is the last pose shown.
                level = DynamicChainLevel{
                    makeDynamicFrameScene(animation.triangles, animation.poses[previous], animation.poses[pose]),
                    *mode.rule};
                reference = sequence.renderNext(*level, settings);
            } else {
                reference = ReferenceRenderer(poseScene(animation, pose))
                                .render(camera, options.width, options.height, settings);
            }
            referenceMs += double(referenceClock.nsecsElapsed()) * 1e-6;
            for (MethodRun& run : runs) {
                QElapsedTimer clock;
                clock.start();
                if (!mode.rule) {
                    run.renderer->setScene(poseScene(animation, pose));
                    run.renderer->render(camera, settings, options.width, options.height);
                } else {
                    if (run.dynamic->levelCount() == 0)
                        run.dynamic->setChain(DynamicChain{settings.rule, {*level}});
                    else
                        run.dynamic->appendLevel(*level);
                    run.dynamic->render(camera, settings, options.width, options.height);
                }
                record(run, testCase, reference, double(clock.nsecsElapsed()) * 1e-6, name.c_str(), mode, pose);
            }
            previous = pose;
        }
        for (const MethodRun& run : runs) {
            std::printf("%-14s %-28s %-20s %6d %9ld %7d %9.3f %9.3f %7d %7d %9.1f %9.1f\n", name.c_str(),
                        mode.name.c_str(), run.id.c_str(), run.frames, run.compared / std::max(run.frames, 1),
                        run.sparse, 100.0 * run.worst, 100.0 * run.sum / std::max(run.frames, 1), run.failing,
                        run.overflowed, run.milliseconds / std::max(run.frames, 1),
                        referenceMs / std::max(run.frames, 1));
            allPass = allPass && run.failing == 0;
        }
        std::fflush(stdout);
    }
    return allPass;
}

} // namespace

int main(int argc, char** argv)
{
    QGuiApplication application(argc, argv);
    QCommandLineParser parser;
    parser.addOptions({{"size", "Frame size (320x240).", "WxH"}, {"step", "Every N-th pose (1).", "N"}});
    parser.addPositionalArgument("animations", "Animation folders or patterns.", "[ANIMATION...]");
    parser.process(application);
    Options options;
    if (parser.isSet("size")) {
        const QStringList parts = parser.value("size").split(QLatin1Char('x'));
        options.width = parts.value(0).toInt();
        options.height = parts.value(1).toInt();
    }
    if (parser.isSet("step"))
        options.step = std::max(1, parser.value("step").toInt());
    for (const QString& a : parser.positionalArguments())
        options.animations.push_back(a.toStdString());
    if (options.animations.empty())
        options.animations = {test::sharedDataPath("anim/samba").string(),
                              test::sharedDataPath("anim/horse-gallop").string()};
    if (options.width < 16 || options.height < 16) {
        std::fprintf(stderr, "--size must be at least 16x16\n");
        return 2;
    }
    render::OffscreenGlContext context;
    std::printf("%s; %dx%d, every %zu. pose, k = 32, clip plane through each pose's centre\n",
                context.capabilities().summary().toUtf8().constData(), options.width, options.height, options.step);
    std::printf("%-14s %-28s %-20s %6s %9s %7s %9s %9s %7s %7s %9s %9s\n", "animation", "rule", "method", "poses",
                "compared", "sparse", "worst %", "mean %", "failing", "overfl.", "gpu ms", "ref ms");
    bool allPass = true;
    for (const std::string& source : options.animations)
        allPass = measureAnimation(source, options, context.context()) && allPass;
    return allPass ? 0 : 1;
}
