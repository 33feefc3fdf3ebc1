#include "core/skinning/skinning_pipeline.h"

#include "core/skinning/skinning_error.h"

#include <chrono>

namespace trimlab {

namespace {

// The bones of `source` into `fit` (and how a count was reached).
void makeBones(const MeshAnimation& animation, const SkinningBoneSource& source, SkinningFit& fit,
               const TaskControl& control)
{
    if (source.segmentation) {
        if (source.segmentation->colors.size() != source.segmentation->labeling.count)
            throw std::invalid_argument("skinning fit: one bone color per segment is required");
        fit.bones = source.segmentation->labeling;
        fit.boneColors = source.segmentation->colors;
        return;
    }
    const auto start = std::chrono::steady_clock::now();
    BoneSegmentation bones;
    try {
        bones = segmentIntoBones(animation, source.segmenter, source.count, control);
    } catch (const OperationCancelled&) {
        throw;
    } catch (const std::invalid_argument& e) {
        throw SkinningBonesError(e.what());
    } catch (const std::runtime_error& e) {
        throw SkinningBonesError(e.what());
    }
    fit.segmentationMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    fit.bones = std::move(bones.labeling);
    fit.boneColors = std::move(bones.colors);
    fit.search = std::move(bones.search);
}

} // namespace

SkinningBoneSource segmentedBones(std::size_t count, unsigned threads)
{
    SkinningBoneSource bones;
    bones.count = count;
    bones.segmenter.partition.clusters = count;
    bones.segmenter.threads = threads;
    return bones;
}

std::shared_ptr<const SkinningFit> runSkinningFit(const MeshAnimation& animation, const SkinningBoneSource& source,
                                                  const SkinningPipelineOptions& options, const TaskControl& control)
{
    auto fit = std::make_shared<SkinningFit>();
    makeBones(animation, source, *fit, control);
    fit->result = fitSkinning(animation, fit->bones, options.fit, control);
    control.throwIfCancelled();
    control.report("reconstruction", 0, 1);
    fit->original = animationPositions(animation);
    if (options.reconstruct)
        fit->approximation = reconstructPoses(fit->result.model);
    control.report("reconstruction", 1, 1);
    return fit;
}

} // namespace trimlab
