#pragma once
/// \file
/// The measuring loop of `trimlab bench`: for one scene and frame size, the exact CPU
/// reference of every view on the camera path (bench_views.h), then every method in turn:
/// one untimed warm-up frame (shader build, allocation), `repeat` timed frames per view,
/// and the last frame of each view compared with the reference (core/trim/trim_agreement.h,
/// the render tests' criteria), then the same frames pipelined as the viewport renders
/// them (the frame period beside the GPU time). A method that throws is recorded with its
/// error and the run goes on.

#include "app/bench_options.h"
#include "app/bench_results.h"
#include "app/bench_scenes.h"

#include "render/trim_renderer.h"

namespace trimlab::app {

class BenchRunner {
public:
    /// `renderer`'s context must stay current while the runner is used.
    BenchRunner(render::TrimRenderer& renderer, const BenchOptions& options);

    /// Appends one cell per method and size for `scene` to `report`. Prints one progress
    /// note per size on stderr.
    void measureScene(const BenchScene& scene, BenchReport& report);

private:
    struct ViewReference;

    [[nodiscard]] std::vector<ViewReference> referenceViews(const ReferenceRenderer& reference, const BenchScene& scene,
                                                            QSize size) const;
    [[nodiscard]] BenchCell measureMethod(render::FragmentMethodKind method, const render::MethodParameters& parameters,
                                          const BenchScene& scene, QSize size, const ReferenceRenderer& reference,
                                          const std::vector<ViewReference>& views);
    void measureView(BenchCell& cell, const BenchScene& scene, const ReferenceRenderer& reference,
                     const ViewReference& view, int index);
    /// `repeat` frames of `camera` pipelined: wall time / frames, the last one's results in.
    [[nodiscard]] double pipelinedPeriod(const BenchScene& scene, QSize size, const Camera& camera);

    render::TrimRenderer& m_renderer;
    const BenchOptions& m_options;
};

} // namespace trimlab::app
