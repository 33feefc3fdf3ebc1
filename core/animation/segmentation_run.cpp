#include "core/animation/segmentation_run.h"

#include "core/animation/segment_coloring.h"

#include <algorithm>
#include <string>

namespace trimlab {

namespace {

void requirePartitionedPoses(const AnimationSegmenter& segmenter)
{
    if (!segmenter.partitionedPoses().empty())
        return;
    const std::size_t poses = segmenter.animation().poseCount();
    const FeatureKind feature = segmenter.settings().feature.kind;
    const std::size_t needed = feature == FeatureKind::Acceleration ? 3 : 2;
    throw SegmentationInputError("the animation has " + std::to_string(poses) + (poses == 1 ? " pose" : " poses") +
                                 "; the " + std::string(featureName(feature)) + " feature needs at least " +
                                 std::to_string(needed));
}

void addVariable(SegmentationResult& result, const TaskControl& control)
{
    control.report("per-pose segments", 0, 1);
    const AnimationSegmenter& segmenter = *result.segmenter;
    result.variable = segmenter.variableSegmentation();
    control.throwIfCancelled();
    result.variableColors = colorSequence(segmenter.graph(), segmenter.vertexAreas(), result.variable);
    control.report("per-pose segments", 1, 1);
}

} // namespace

std::size_t SegmentationResult::variableIndexAt(std::size_t pose) const
{
    const std::vector<std::size_t>& poses = segmenter->partitionedPoses();
    const auto after = std::upper_bound(poses.begin(), poses.end(), pose);
    const auto index = std::size_t(after - poses.begin());
    return std::min(index == 0 ? 0 : index - 1, variable.size() - 1);
}

std::shared_ptr<const SegmentationResult>
runSegmentation(MeshAnimation animation, const SegmentationRunOptions& options, const TaskControl& control)
{
    auto segmenter = std::make_shared<AnimationSegmenter>(std::move(animation), options.settings);
    segmenter->run(control);
    requirePartitionedPoses(*segmenter);
    auto result = std::make_shared<SegmentationResult>();
    result->segmenter = std::move(segmenter);
    if (options.variable)
        addVariable(*result, control);
    return result;
}

std::shared_ptr<const SegmentationResult> completeSegmentation(std::shared_ptr<const AnimationSegmenter> segmenter,
                                                               const TaskControl& control)
{
    auto result = std::make_shared<SegmentationResult>();
    result->segmenter = std::move(segmenter);
    addVariable(*result, control);
    return result;
}

} // namespace trimlab
