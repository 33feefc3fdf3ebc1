#include "core/skinning/proxy_bones.h"

#include "core/animation/segment_coloring.h"
#include "core/animation/segment_count_search.h"

namespace trimlab {

BoneSegmentation segmentIntoBones(const MeshAnimation& animation, const SegmenterSettings& settings,
                                  std::size_t count, const TaskControl& control)
{
    AnimationSegmenter segmenter(animation, settings);
    BoneSegmentation bones;
    bones.labeling = segmentIntoCount(segmenter, count, control).segmentation;
    bones.colors = colorSegments(segmenter.graph(), bones.labeling, segmenter.vertexAreas());
    return bones;
}

} // namespace trimlab
