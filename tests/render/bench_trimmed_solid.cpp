// Benchmark of the trimmed-solid export (core/solid) beside the live path: per mesh of
// ../shared/data/selfintersect and the self-crossing demos, the export's time (exact
// refinement + cell windings) next to the time of one trimmed frame on the GPU
// (kplus-array, 1024×768), and the agreement of the export, rendered plainly (positive
// index), with the image-space trim of the same rule from 20 directions (AB_LL, exact,
// 256×192: pixels covered by either, equal coverage and depth within 1e-4).
//
//   xvfb-run -a ./build/tests/render/bench_trimmed_solid [alternating-border|nonzero|...] [mesh...]
#include "test_paths.h"
#include "view_directions.h"

#include "core/catalog/scene_source.h"
#include "core/solid/trimmed_solid.h"
#include "core/trim/static_rule.h"
#include "render/gl/offscreen_gl_context.h"
#include "render/trim_renderer.h"

#include <glm/gtc/constants.hpp>

#include <QGuiApplication>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <vector>

using namespace trimlab;

namespace {

std::vector<std::string> defaultSources()
{
    std::vector<std::string> sources{"demo:pushed-sphere", "demo:crossing-loop"};
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(test::sharedDataPath("selfintersect")))
        if (entry.is_regular_file())
            files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    sources.insert(sources.end(), files.begin(), files.end());
    return sources;
}

double frameMilliseconds(render::TrimRenderer& renderer, const Scene& scene, const TrimSettings& settings)
{
    renderer.setMethod(render::FragmentMethodKind::KPlusArray);
    renderer.setScene(scene);
    const Camera camera = fitCamera(scene.worldBounds(), 1024.0 / 768.0);
    std::vector<double> times;
    for (int i = 0; i < 4; ++i) {
        renderer.render(camera, settings, 1024, 768);
        times.push_back(renderer.lastStats().wallMilliseconds);
    }
    std::sort(times.begin() + 1, times.end()); // the first frame allocates
    return times[2];
}

struct Agreement {
    long covered = 0;
    long agreeing = 0;
};

Agreement viewAgreement(render::TrimRenderer& renderer, const Scene& scene, const TrimSettings& settings,
                        const Scene& exported)
{
    constexpr int kWidth = 256, kHeight = 192, kViews = 20;
    TrimSettings plain;
    plain.rule = StaticRule::PositiveIndex;
    renderer.setMethod(render::FragmentMethodKind::ABufferLinkedList);
    Agreement agreement;
    for (int i = 0; i < kViews; ++i) {
        const Camera camera =
            fitCamera(scene.worldBounds(), double(kWidth) / kHeight, test::fibonacciDirection(i, kViews));
        renderer.setScene(scene);
        renderer.render(camera, settings, kWidth, kHeight);
        const TrimImage a = renderer.readTrimImage();
        renderer.setScene(exported);
        renderer.render(camera, plain, kWidth, kHeight);
        const TrimImage b = renderer.readTrimImage();
        for (std::size_t p = 0; p < a.pixels.size(); ++p) {
            const TrimPixel& x = a.pixels[p];
            const TrimPixel& z = b.pixels[p];
            if (!x.covered() && !z.covered())
                continue;
            ++agreement.covered;
            agreement.agreeing += x.covered() && z.covered() &&
                                          std::abs(x.viewDepth - z.viewDepth) <= 1e-4f * std::max(x.viewDepth, 1e-3f)
                                      ? 1
                                      : 0;
        }
    }
    return agreement;
}

} // namespace

int main(int argc, char** argv)
{
    QGuiApplication application(argc, argv);
    TrimSettings settings;
    settings.rule = StaticRule::AlternatingBorder;
    std::vector<std::string> sources;
    for (int i = 1; i < argc; ++i) {
        if (const std::optional<StaticRule> rule = parseStaticRule(argv[i]))
            settings.rule = *rule;
        else
            sources.emplace_back(argv[i]);
    }
    if (sources.empty())
        sources = defaultSources();
    render::OffscreenGlContext gl;
    render::TrimRenderer renderer(gl.context());
    std::printf("rule %s; %s\n", ruleName(settings.rule).c_str(),
                renderer.capabilities().summary().toUtf8().constData());
    std::printf("%-34s %9s %9s %9s %6s %10s %10s %8s %9s %s\n", "mesh", "triangles", "refined", "kept", "nm-e",
                "export ms", "frame ms", "ratio", "agree %", "pixels");
    for (const std::string& source : sources) {
        LoadedScene loaded;
        try {
            loaded = loadScene(source);
        } catch (const std::exception& e) {
            std::printf("%-34s could not be loaded: %s\n", source.c_str(), e.what());
            continue;
        }
        const std::string name = std::filesystem::path(source).filename().string();
        if (!loaded.trimmable()) {
            std::printf("%-34s skipped: %s\n", name.c_str(), loaded.trimUnavailableReason().c_str());
            continue;
        }
        try {
            const TrimmedSolid solid = trimmedSolid(loaded.scene, settings);
            const double exportMs = solid.stats.refineMs + solid.stats.windingMs;
            const double frameMs = frameMilliseconds(renderer, loaded.scene, settings);
            Scene exported;
            exported.objects.push_back({"export", solid.mesh, glm::dmat4(1.0)});
            const Agreement agreement = viewAgreement(renderer, loaded.scene, settings, exported);
            std::printf("%-34s %9zu %9zu %9zu %6zu %10.0f %10.2f %8.0f %9.3f %ld\n", name.c_str(),
                        solid.stats.inputTriangles, solid.stats.refinedFaces, solid.stats.keptFaces,
                        solid.stats.nonManifoldEdges, exportMs, frameMs, exportMs / frameMs,
                        100.0 * double(agreement.agreeing) / double(std::max(agreement.covered, 1L)),
                        agreement.covered);
        } catch (const std::exception& e) {
            std::printf("%-34s failed: %s\n", name.c_str(), e.what());
        }
        std::fflush(stdout);
    }
    return 0;
}
