#include "render/mfr/method_factory.h"

#include "render/mfr/abuffer_fixed.h"
#include "render/mfr/abuffer_linked_list.h"
#include "render/mfr/dual_peeling.h"
#include "render/mfr/f2b_peeling.h"
#include "render/mfr/kplus_buffer.h"
#include "render/mfr/kplus_s_buffer.h"
#include "render/mfr/s_buffer.h"
#include "render/mfr/two_pass.h"

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
    case FragmentMethodKind::SBuffer:
        return std::make_unique<SBuffer>(gl);
    case FragmentMethodKind::KPlusSBuffer:
        return std::make_unique<KPlusSBuffer>(gl);
    case FragmentMethodKind::ABufferFixed:
        return std::make_unique<ABufferFixed>(gl);
    case FragmentMethodKind::ABufferLinkedList:
        return std::make_unique<ABufferLinkedList>(gl);
    // peeling methods (F2B, DUAL, two-pass)
    case FragmentMethodKind::PeelingF2B:
        return std::make_unique<F2BPeeling>(gl);
    case FragmentMethodKind::PeelingDual:
        return std::make_unique<DualPeeling>(gl);
    case FragmentMethodKind::TwoPass:
        return std::make_unique<TwoPassTrim>(gl);
    default:
        break;
    }
    throw std::invalid_argument("multi-fragment method not available in this build");
}

} // namespace trimlab::render
