#include "render/memory_fallback.h"

namespace trimlab::render {

std::optional<FragmentMethodKind> memoryFallbackAfter(FragmentMethodKind failed, bool dynamicRules,
                                                      bool needsInspection)
{
    switch (failed) {
    case FragmentMethodKind::KPlusArray:
    case FragmentMethodKind::KPlusHeap:
    case FragmentMethodKind::ABufferFixed:
        return FragmentMethodKind::SBuffer;
    case FragmentMethodKind::SBuffer:
    case FragmentMethodKind::KPlusSBuffer:
    case FragmentMethodKind::ABufferLinkedList:
    case FragmentMethodKind::TwoPass:
        if (dynamicRules || needsInspection)
            return std::nullopt;
        return FragmentMethodKind::PeelingF2B;
    case FragmentMethodKind::PeelingF2B:
    case FragmentMethodKind::PeelingDual:
        return std::nullopt;
    }
    return std::nullopt;
}

} // namespace trimlab::render
