#include "mfr/method_factory.h"

#include "mfr/kplus_buffer.h"

#include <stdexcept>

namespace trimlab::render {

std::unique_ptr<FragmentMethod> createFragmentMethod(FragmentMethodKind kind, GlFunctions& gl)
{
    switch (kind) {
    case FragmentMethodKind::KPlusArray:
        return std::make_unique<KPlusBuffer>(gl, false);
    case FragmentMethodKind::KPlusHeap:
        return std::make_unique<KPlusBuffer>(gl, true);
    // buffer methods (S-buffer, K+B-SB, AB_FP, AB_LL)
    // peeling methods (F2B, DUAL, two-pass)
    default:
        break;
    }
    throw std::invalid_argument("multi-fragment method not available in this build");
}

} // namespace trimlab::render
