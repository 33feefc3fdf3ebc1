#include "core/skinning/proxy_bones.h"

#include "core/animation/segment_coloring.h"

namespace trimlab {

BoneSegmentation segmentIntoBones(const MeshAnimation& animation, const SegmenterSettings& settings, std::size_t count,
                                  const TaskControl& control)
{
    AnimationSegmenter segmenter(animation, settings);
    BoneSegmentation bones;
    bones.search = segmentIntoCount(segmenter, count, control);
    bones.labeling = std::move(bones.search.segmentation);
    bones.colors = colorSegments(segmenter.graph(), bones.labeling, segmenter.vertexAreas());
    return bones;
}

} // namespace trimlab
