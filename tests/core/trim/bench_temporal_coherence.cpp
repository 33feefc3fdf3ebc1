// Temporal coherence of the static and dynamic rules over mesh animations, measured (not a
// test: it never fails and is not registered with CTest). Run by hand:
//   nice -n 10 build/tests/core/trim/bench_temporal_coherence
//       ../shared/data/anim/horse-gallop ../shared/data/anim/horse-collapse ../shared/data/anim/samba
// (one line).
// Options: --size WxH (160x120), --step N (every N-th pose, 1), --tolerance F (the depth
// within which a fragment counts as unmoved, as a fraction of the bounding-box diagonal,
// 1e-3), --threads N, --pairs (one line per pose pair and rule as well), --verify K (the
// first K poses after the rest pose are also rendered from scratch by ReferenceRenderer /
// DynamicReferenceRenderer over animationChain, and the pixels whose first kept fragment
// differs from the carried classification are counted: 0 expected).
// An open animation is closed first (core/animation/closed_animation.h: a fan to each
// loop's centroid, the same triangles in every pose). One camera is fitted to all poses.
// For each pair of consecutive poses and each rule it counts, as defined in
// core/trim/temporal_coherence.h, the pixels with an unmoved fragment and of those the
// ones where a class beside an unmoved fragment flips (all, visible, unswept), from the
// exact per-ray classification (core/trim/frame_sequence_classifier.h); the dynamic
// rules classify the rest pose (pose 0) by the alternating border, as the thesis does.
// The table gives per rule the mean and max over the pairs of flipping / unmoved pixels
// and the number of pairs with any flip.
#include "core/animation/animation_chain.h"
#include "core/animation/animation_loader.h"
#include "core/animation/closed_animation.h"
#include "core/mesh/mesh_validation.h"
#include "core/trim/dynamic_reference_renderer.h"
#include "core/trim/frame_sequence_classifier.h"
#include "core/trim/reference_renderer.h"
#include "core/trim/temporal_coherence.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QElapsedTimer>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

using namespace trimlab;

namespace {

struct Options {
    int width = 160;
    int height = 120;
    std::size_t step = 1;
    double tolerance = 1e-3;
    unsigned threads = 0;
    bool pairs = false;
    std::size_t verify = 0;
};

struct Mode {
    std::string name;
    SequenceRule rule;
};

std::vector<Mode> modes()
{
    std::vector<Mode> result;
    for (StaticRule rule : {StaticRule::Parity, StaticRule::PositiveIndex, StaticRule::AlternatingBorder}) {
        SequenceRule r;
        r.staticRule = rule;
        result.push_back({ruleName(rule) + " (static)", r});
    }
    for (SequenceReference reference : {SequenceReference::Previous, SequenceReference::First})
        for (DynamicRule rule : {DynamicRule::ConstructiveAdditive, DynamicRule::ConstructiveSubtractive,
                                 DynamicRule::Confluent, DynamicRule::HomogeneousConfluent}) {
            SequenceRule r;
            r.dynamicRule = rule;
            r.reference = reference;
            const char* against = reference == SequenceReference::Previous ? "previous" : "rest";
            result.push_back({std::string(dynamicRuleName(rule)) + " / " + against, r});
        }
    return result;
}

/// Mean, max and count of nonzero values of one column over the pairs.
struct Column {
    double sum = 0.0;
    double max = 0.0;
    std::size_t nonzero = 0;
    void add(double value)
    {
        sum += value;
        max = std::max(max, value);
        nonzero += value > 0.0 ? 1 : 0;
    }
};

struct ModeSummary {
    Column flipped, visible, unswept, unmoved;
    std::size_t pairs = 0;
    std::size_t verifyDiffering = 0;
    std::size_t unresolved = 0;
    double seconds = 0.0;
};

MeshAnimation loadClosed(const std::string& source, const Options& options)
{
    MeshAnimation animation = loadAnimation(source);
    const MeshValidationReport open = validateMesh(animation.poseMesh(animation.restPose));
    if (open.boundaryEdges.any()) {
        animation = closeAnimationHoles(animation);
        std::printf("  open: %zu boundary edges, closed by fans (%zu triangles added)\n", open.boundaryEdges.count,
                    animation.triangleCount() - open.triangleCount);
    }
    const MeshValidationReport closed = validateMesh(animation.poseMesh(animation.restPose));
    std::printf("  rest pose: %zu vertices, %zu triangles, trimmable: %s\n", closed.vertexCount, closed.triangleCount,
                closed.trimmable() ? "yes" : closed.trimUnavailableReason().c_str());
    if (options.step > 1) {
        MeshAnimation sampled = animation;
        sampled.poses.clear();
        for (std::size_t p = 0; p < animation.poseCount(); p += options.step)
            sampled.poses.push_back(animation.poses[p]);
        sampled.poseNames.clear();
        sampled.poseTimes.clear();
        sampled.restPose = 0;
        animation = std::move(sampled);
    }
    return animation;
}

Bounds allPoses(const MeshAnimation& animation)
{
    Bounds bounds;
    for (const auto& pose : animation.poses)
        for (const glm::vec3& p : pose)
            bounds.extend(glm::dvec3(p));
    return bounds;
}

/// The median over poses of the median vertex step to the next pose, / diagonal.
double medianStep(const MeshAnimation& animation, double diagonal)
{
    std::vector<double> medians;
    for (std::size_t p = 1; p < animation.poseCount(); ++p) {
        std::vector<double> steps;
        for (std::size_t v = 0; v < animation.vertexCount(); ++v)
            steps.push_back(double(glm::length(animation.poses[p][v] - animation.poses[p - 1][v])));
        std::nth_element(steps.begin(), steps.begin() + std::ptrdiff_t(steps.size() / 2), steps.end());
        medians.push_back(steps[steps.size() / 2] / diagonal);
    }
    if (medians.empty())
        return 0.0;
    std::nth_element(medians.begin(), medians.begin() + std::ptrdiff_t(medians.size() / 2), medians.end());
    return medians[medians.size() / 2];
}

/// The triangle each pixel shows (its first kept fragment; −1: none).
std::vector<std::int32_t> shownTriangles(const FrameFragments& frame)
{
    std::vector<std::int32_t> shown;
    for (const auto& fragments : frame.pixels) {
        auto kept = std::find_if(fragments.begin(), fragments.end(), [](const auto& f) { return f.kept(); });
        shown.push_back(kept == fragments.end() ? -1 : std::int32_t(kept->triangle));
    }
    return shown;
}

/// Pixels where `frame` (pose `pose`) shows another triangle than the reference renderers
/// show when they render the pose from scratch.
std::size_t differingFromReference(const MeshAnimation& animation, std::size_t pose, const Camera& camera,
                                   const SequenceRule& rule, const FrameFragments& frame, const Options& options)
{
    TrimSettings settings;
    settings.rule = rule.staticRule;
    TrimImage image;
    if (!rule.dynamicRule) {
        Scene scene;
        scene.objects.emplace_back();
        scene.objects.back().mesh = animation.poseMesh(pose);
        image = ReferenceRenderer(scene).render(camera, options.width, options.height, settings, options.threads).trim;
    } else {
        const PoseReference reference =
            rule.reference == SequenceReference::Previous ? PoseReference::Previous : PoseReference::Rest;
        const DynamicChain chain = *animationChain(animation, pose, reference, *rule.dynamicRule, rule.staticRule);
        image = withMeshIds(DynamicReferenceRenderer(chain)
                                .render(camera, options.width, options.height, settings, options.threads)
                                .trim,
                            chain.levels.back().frame);
    }
    const std::vector<std::int32_t> shown = shownTriangles(frame);
    std::size_t differing = 0;
    for (std::size_t i = 0; i < shown.size(); ++i)
        differing += shown[i] != image.pixels[i].primitiveId ? 1 : 0;
    return differing;
}

ModeSummary measure(const MeshAnimation& animation, const Camera& camera, const Mode& mode, double depthTolerance,
                    const Options& options)
{
    QElapsedTimer timer;
    timer.start();
    ModeSummary summary;
    FrameSequenceClassifier classifier(animation.triangles, camera, options.width, options.height, mode.rule,
                                       options.threads);
    FrameFragments before = classifier.next(animation.poses[0]);
    for (std::size_t p = 1; p < animation.poseCount(); ++p) {
        FrameFragments after = classifier.next(animation.poses[p]);
        if (p <= options.verify)
            summary.verifyDiffering += differingFromReference(animation, p, camera, mode.rule, after, options);
        const CoherenceCounts c = compareFrames(before, after, depthTolerance);
        summary.flipped.add(c.fractionOfUnmoved(c.flippedPixels));
        summary.visible.add(c.fractionOfUnmoved(c.trimFlippedPixels));
        summary.unswept.add(c.fractionOfUnmoved(c.unsweptFlippedPixels));
        summary.unmoved.add(double(c.unmovedPixels));
        summary.unresolved += c.unresolvedPixels;
        ++summary.pairs;
        if (options.pairs)
            std::printf("    %-32s %3zu-%3zu unmoved %6zu  flip %6zu  visible %6zu  unswept %6zu\n", mode.name.c_str(),
                        p - 1, p, c.unmovedPixels, c.flippedPixels, c.trimFlippedPixels, c.unsweptFlippedPixels);
        before = std::move(after);
    }
    summary.seconds = double(timer.elapsed()) / 1000.0;
    return summary;
}

void printRow(const std::string& name, const ModeSummary& s, const Options& options)
{
    if (options.verify > 0)
        std::printf("  %-32s poses 1-%zu against the reference renderers: %zu pixels differ\n", name.c_str(),
                    std::min(options.verify, s.pairs), s.verifyDiffering);
    const double n = double(std::max<std::size_t>(s.pairs, 1));
    std::printf("  %-32s %8.0f | %6.3f %6.3f %3zu | %6.3f %6.3f %3zu | %6.3f %6.3f %3zu | %6zu %6.1f\n", name.c_str(),
                s.unmoved.sum / n, 100.0 * s.flipped.sum / n, 100.0 * s.flipped.max, s.flipped.nonzero,
                100.0 * s.visible.sum / n, 100.0 * s.visible.max, s.visible.nonzero, 100.0 * s.unswept.sum / n,
                100.0 * s.unswept.max, s.unswept.nonzero, s.unresolved, s.seconds);
}

void runAnimation(const std::string& source, const Options& options)
{
    std::printf("%s\n", source.c_str());
    const MeshAnimation animation = loadClosed(source, options);
    const Bounds bounds = allPoses(animation);
    const double diagonal = 2.0 * bounds.radius();
    const Camera camera = fitCamera(bounds, double(options.width) / double(options.height));
    std::printf("  %zu poses (step %zu), %dx%d, median vertex step %.2e of the diagonal, unmoved within %.1e\n",
                animation.poseCount(), options.step, options.width, options.height, medianStep(animation, diagonal),
                options.tolerance);
    std::printf("  %-32s %8s | %-17s | %-17s | %-17s | %6s %6s\n", "rule", "unmoved", "flip % mean max n",
                "visible % mean max n", "unswept % mean max n", "unres", "s");
    for (const Mode& mode : modes()) {
        const ModeSummary summary = measure(animation, camera, mode, options.tolerance * diagonal, options);
        printRow(mode.name, summary, options);
        std::fflush(stdout);
    }
}

} // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    QCommandLineParser parser;
    parser.addPositionalArgument("animation", "Mesh sequence folders or glTF files.");
    parser.addOption({"size", "Viewport WxH.", "WxH", "160x120"});
    parser.addOption({"step", "Every N-th pose.", "N", "1"});
    parser.addOption({"tolerance", "Unmoved depth tolerance / diagonal.", "F", "1e-3"});
    parser.addOption({"threads", "Worker threads (0: all).", "N", "0"});
    parser.addOption({"pairs", "One line per pose pair and rule."});
    parser.addOption({"verify", "Check the first K poses against the reference renderers.", "K", "0"});
    parser.addHelpOption();
    parser.process(app);
    Options options;
    const QStringList size = parser.value("size").split('x');
    if (size.size() == 2) {
        options.width = size[0].toInt();
        options.height = size[1].toInt();
    }
    options.step = std::max<std::size_t>(1, parser.value("step").toULongLong());
    options.tolerance = parser.value("tolerance").toDouble();
    options.threads = parser.value("threads").toUInt();
    options.pairs = parser.isSet("pairs");
    options.verify = parser.value("verify").toULongLong();
    try {
        for (const QString& source : parser.positionalArguments())
            runAnimation(source.toStdString(), options);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
    return 0;
}
