#include "render/content_owner.h"

namespace trimlab::render {

std::string_view contentOwnerName(ContentOwner owner)
{
    switch (owner) {
    case ContentOwner::None:
        return "nobody";
    case ContentOwner::DesignHistory:
        return "design history";
    case ContentOwner::Skeleton:
        return "skeleton";
    case ContentOwner::AnimationPlayback:
        return "animation playback";
    case ContentOwner::Skinning:
        return "skinning";
    case ContentOwner::Segmentation:
        return "segmentation";
    case ContentOwner::BrushRegion:
        return "brush region";
    }
    return "unknown";
}

} // namespace trimlab::render
