// Skinning accuracy and time against its anchors, Dem Bones and the thesis (not a test: it
// never fails and is not registered with CTest). Run by hand, e.g.
//   build/tests/core/skinning/bench_skinning --bones 5,10,20 ../shared/data/anim/dem-bones/frames
//   build/tests/core/skinning/bench_skinning --bones 30 ../shared/data/anim/samba
// For each animation and bone count it segments the animation into exactly B parts (as
// `trimlab skin` does), prints the segment sizes, and fits every variant below from the
// same segmentation, printing side by side:
//   E_RMS fit       1000·‖A − A′‖_F / √(3nk) of the fitted model (skinning_error.h)
//   E_RMS exported  the same for the positions the written glTF plays (computed exactly
//                   as a viewer does from the file's float values, skinning_gltf.h)
//   RMSE exported   ‖A − A′‖_F / √(nk), Dem Bones' "RMSE"
//   fit s           wall-clock seconds of fitSkinning (weights, fit, corrections)
// and, where known, the anchors: Dem Bones' RMSE on its sample (its upstream log, 8
// weights per vertex, 30 iterations; ../shared/data/SOURCES.md 1.7) and the thesis's
// Table 4.1 E_RMS (p2p-skinning, FESAM, SAD) for samba and the elephant.
#include "core/animation/animation_loader.h"
#include "core/animation/animation_segmenter.h"
#include "core/animation/segment_count_search.h"
#include "core/animation/segment_sizes.h"
#include "core/skinning/skinning_error.h"
#include "core/skinning/skinning_fitter.h"
#include "core/skinning/skinning_gltf.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QElapsedTimer>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <map>
#include <string>
#include <vector>

using namespace trimlab;

namespace {

struct Variant {
    const char* name;
    SkinningFitOptions options;
};

SkinningFitOptions fitOptions(bool exported, SkinningMethod method, SkinningChain chain, bool corrections,
                              std::size_t influences = kDefaultInfluences)
{
    SkinningFitOptions o;
    o.fitExported = exported;
    o.method = method;
    o.chain = chain;
    o.weightCorrections = o.vertexCorrections = corrections;
    o.decomposition.maxInfluences = influences;
    return o;
}

std::vector<Variant> variants()
{
    using M = SkinningMethod;
    using C = SkinningChain;
    return {
        {"thesis p2p LBS, no corrections", fitOptions(false, M::Lbs, C::PoseToPose, false)},
        {"thesis p2p LBS, corrections v,w", fitOptions(false, M::Lbs, C::PoseToPose, true)},
        {"DQS rest-to-pose v,w (best before)", fitOptions(false, M::Dqs, C::RestToPose, true)},
        {"LBS rest-to-pose v,w (iterated)", fitOptions(false, M::Lbs, C::RestToPose, true)},
        {"rigid joints, 4 influences (default)", fitOptions(true, M::Lbs, C::RestToPose, true)},
        {"rigid joints, 8 influences", fitOptions(true, M::Lbs, C::RestToPose, true, 8)},
    };
}

// Anchors by folder name and bone count.
std::string anchor(const std::string& source, std::size_t bones)
{
    const std::map<std::size_t, const char*> demBones{
        {5, "Dem Bones RMSE 0.026754"}, {10, "Dem Bones RMSE 0.015583"}, {20, "Dem Bones RMSE 0.00986339"}};
    if (source.find("dem-bones") != std::string::npos && demBones.count(bones))
        return demBones.at(bones);
    if (source.find("samba") != std::string::npos && bones == 30)
        return "thesis Table 4.1, 30 proxy joints: E_RMS p2p-skinning 1.98, FESAM 1.17, SAD 12.6";
    if (source.find("elephant") != std::string::npos && bones == 25)
        return "thesis Table 4.1 (42321 vertices, 48 poses; the shared elephant differs), 25 proxy joints: E_RMS "
               "p2p-skinning 2.2, FESAM 1.39, SAD 13.3";
    return "no published figure for this animation and bone count";
}

void printSegmentSizes(const VertexLabeling& segmentation)
{
    const SegmentSizes found = segmentSizes(segmentation);
    const std::vector<std::size_t>& sizes = found.sorted;
    std::printf("  segments: %zu; vertices per segment: smallest %zu, median %zu, largest %zu; under 1 %% of the "
                "vertices: %zu\n  sizes:",
                sizes.size(), sizes.front(), sizes[sizes.size() / 2], sizes.back(), found.underOnePercent);
    for (std::size_t s : sizes)
        std::printf(" %zu", s);
    std::printf("\n");
}

void benchAnimation(const std::string& source, const std::vector<std::size_t>& boneCounts)
{
    const MeshAnimation loaded = loadAnimation(source);
    std::printf("%s: %zu poses, %zu vertices\n", source.c_str(), loaded.poseCount(), loaded.vertexCount());
    const std::vector<PosePositions> original = animationPositions(loaded);
    for (std::size_t bones : boneCounts) {
        SegmenterSettings settings;
        settings.partition.clusters = bones;
        AnimationSegmenter segmenter(loaded, settings);
        const SegmentCountSearch segmentation = segmentIntoCount(segmenter, bones);
        std::printf(" %zu bones (%s)\n", bones, anchor(source, bones).c_str());
        printSegmentSizes(segmentation.segmentation);
        std::printf("  %-38s %10s %10s %12s %8s %6s\n", "variant", "E_RMS fit", "exported", "RMSE export", "fit s",
                    "iters");
        for (const Variant& v : variants()) {
            QElapsedTimer timer;
            timer.start();
            const SkinningFitResult fit = fitSkinning(loaded, segmentation.segmentation, v.options);
            const double seconds = double(timer.nsecsElapsed()) * 1e-9;
            SkinExportOptions exportOptions;
            exportOptions.target = &original;
            const SkinnedGltf gltf = skinnedGltf(fit.model, 24.0, true, exportOptions);
            const SkinningError exported = measureSkinningError(original, gltf.report.positions, loaded.restPose);
            std::printf("  %-38s %10.4f %10.4f %12.6g %8.1f %6zu\n", v.name, fit.error.eRms, exported.eRms,
                        exported.rmse, seconds, fit.iterations);
            std::fflush(stdout);
        }
    }
}

std::vector<std::size_t> parseCounts(const QString& text)
{
    std::vector<std::size_t> counts;
    for (const QString& part : text.split(',', Qt::SkipEmptyParts))
        counts.push_back(std::size_t(part.toULongLong()));
    return counts;
}

} // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    QCommandLineParser parser;
    parser.setApplicationDescription("Skinning variants side by side with Dem Bones and the thesis.");
    parser.addOption({"bones", "Comma-separated bone counts. Default: 5,10,20.", "list", "5,10,20"});
    parser.addPositionalArgument("animation", "Animation folders, patterns or glTF files.");
    parser.addHelpOption();
    parser.process(app);
    try {
        for (const QString& source : parser.positionalArguments())
            benchAnimation(source.toStdString(), parseCounts(parser.value("bones")));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_skinning: %s\n", e.what());
        return 1;
    }
    return 0;
}
