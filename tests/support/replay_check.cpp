#include "replay_check.h"

#include "render/dynamic_trim_renderer.h"

#include "core/timeline/frame_chain.h"
#include "core/trim/dynamic_reference_renderer.h"
#include "core/trim/reference_renderer.h"

#include <set>

namespace trimlab::test {

std::optional<QString> checkDynamicChainAgainstReference(render::TrimRenderer& renderer,
                                                         render::FragmentMethodKind method, const DynamicChain& chain,
                                                         const MethodCase& testCase, QString* summary)
{
    renderer.setMethod(method);
    renderer.setParameters(testCase.parameters);
    render::DynamicTrimRenderer dynamic(renderer);
    dynamic.setChain(chain);
    dynamic.render(testCase.camera, testCase.settings, testCase.width, testCase.height);
    const ReferenceResult reference =
        DynamicReferenceRenderer(chain).render(testCase.camera, testCase.width, testCase.height, testCase.settings);
    return checkFrameAgainstReference(renderer, testCase, reference, {}, summary);
}

StaticDynamicDifference compareStaticAndDynamic(const timeline::Timeline& design, const DynamicChain& chain,
                                                const Camera& camera, int width, int height,
                                                const TrimSettings& settings)
{
    StaticDynamicDifference result;
    const DynamicFrameScene& shown = chain.levels.back().frame;
    result.dynamic = withMeshIds(DynamicReferenceRenderer(chain).render(camera, width, height, settings).trim, shown);
    const Scene current = timeline::frameScene(design, design.frameCount() - 1);
    result.staticImage = ReferenceRenderer(current).render(camera, width, height, settings).trim;
    // The triangles the last set moved, at their current position.
    const std::vector<std::uint32_t>& movedList = shown.meshTriangle[kDynamicObjectCurrentOnly];
    const std::set<std::int32_t> moved(movedList.begin(), movedList.end());
    for (std::size_t i = 0; i < result.dynamic.pixels.size(); ++i) {
        const TrimPixel& d = result.dynamic.pixels[i];
        const TrimPixel& s = result.staticImage.pixels[i];
        if (d.primitiveId == s.primitiveId)
            continue;
        ++result.differing;
        if (!moved.count(d.primitiveId) && !moved.count(s.primitiveId))
            ++result.elsewhere;
        if (s.primitiveId >= 0 && d.viewDepth > s.viewDepth)
            ++result.deeper;
    }
    return result;
}

} // namespace trimlab::test
