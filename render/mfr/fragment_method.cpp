#include "mfr/fragment_method.h"

#include <stdexcept>

namespace trimlab::render {

const std::vector<MethodInfo>& fragmentMethods()
{
    static const std::vector<MethodInfo> methods = {
        {FragmentMethodKind::KPlusArray, "kplus-array", "k⁺-buffer (max-array)", true, true, false},
        {FragmentMethodKind::KPlusHeap, "kplus-heap", "k⁺-buffer (max-heap)", true, true, false},
        // buffer methods (S-buffer, K+B-SB, AB_FP, AB_LL)
        // peeling methods (F2B, DUAL, two-pass)
    };
    return methods;
}

const MethodInfo& methodInfo(FragmentMethodKind kind)
{
    for (const MethodInfo& info : fragmentMethods())
        if (info.kind == kind)
            return info;
    throw std::invalid_argument("multi-fragment method not available in this build");
}

std::optional<FragmentMethodKind> parseFragmentMethod(std::string_view id)
{
    for (const MethodInfo& info : fragmentMethods())
        if (info.id == id)
            return info.kind;
    return std::nullopt;
}

} // namespace trimlab::render
