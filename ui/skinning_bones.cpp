#include "skinning_bones.h"

#include "animation/segment_coloring.h"
#include "animation/segment_count_search.h"

namespace trimlab::ui {

BoneSegmentation segmentIntoBones(const MeshAnimation& animation, const SegmenterSettings& settings,
                                  std::size_t count, const TaskControl& control)
{
    AnimationSegmenter segmenter(animation, settings);
    BoneSegmentation bones;
    bones.labeling = segmentIntoCount(segmenter, count, control).segmentation;
    bones.colors = colorSegments(segmenter.graph(), bones.labeling, segmenter.vertexAreas());
    return bones;
}

} // namespace trimlab::ui
