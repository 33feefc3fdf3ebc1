#include "ui/skinning/skinning_result.h"

#include "core/skinning/skinning_error.h"

#include <stdexcept>

namespace trimlab::ui {

std::shared_ptr<const SkinningFit> runSkinningFit(const MeshAnimation& animation, VertexLabeling bones,
                                                  std::vector<WheelColor> boneColors,
                                                  const SkinningFitOptions& options, const TaskControl& control)
{
    if (boneColors.size() != bones.count)
        throw std::invalid_argument("skinning fit: one bone color per segment is required");
    auto fit = std::make_shared<SkinningFit>();
    fit->result = fitSkinning(animation, bones, options, control);
    control.throwIfCancelled();
    control.report("reconstruction", 0, 1);
    fit->original = animationPositions(animation);
    fit->approximation = reconstructPoses(fit->result.model);
    control.report("reconstruction", 1, 1);
    fit->bones = std::move(bones);
    fit->boneColors = std::move(boneColors);
    return fit;
}

} // namespace trimlab::ui
