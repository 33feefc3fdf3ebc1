#include "render/mfr/fragment_method.h"

#include <stdexcept>

namespace trimlab::render {

const std::vector<MethodInfo>& fragmentMethods()
{
    static const std::vector<MethodInfo> methods = {
        {FragmentMethodKind::KPlusArray, "kplus-array", "k⁺-buffer (max-array)", true, true, false, true, true, false},
        {FragmentMethodKind::KPlusHeap, "kplus-heap", "k⁺-buffer (max-heap)", true, true, false, true, true, false},
        // buffer methods (S-buffer, K+B-SB, AB_FP, AB_LL)
        {FragmentMethodKind::SBuffer, "s-buffer", "S-buffer", false, false, true, true, true, true},
        {FragmentMethodKind::KPlusSBuffer, "kplus-sbuffer", "K⁺B-SB", true, true, true, true, true, true},
        {FragmentMethodKind::ABufferFixed, "abuffer-fixed", "AB_FP (fixed arrays)", true, true, false, true, true,
         false},
        {FragmentMethodKind::ABufferLinkedList, "abuffer-linked-list", "AB_LL (linked lists)", false, false, false,
         true, true, true},
        // peeling methods (F2B, DUAL, two-pass)
        {FragmentMethodKind::PeelingF2B, "peeling-f2b", "F2B depth peeling", false, false, false, false, false, true},
        {FragmentMethodKind::PeelingDual, "peeling-dual", "Dual depth peeling", false, false, false, false, false,
         true},
        {FragmentMethodKind::TwoPass, "two-pass", "Two-pass (first layer only)", true, false, false, false, false,
         false},
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

const char* lockDescription(const MethodStats& stats)
{
    if (!stats.usesLock)
        return "none";
    return stats.interlock ? "fragment shader interlock" : "spin-lock";
}

std::optional<FragmentMethodKind> parseFragmentMethod(std::string_view id)
{
    for (const MethodInfo& info : fragmentMethods())
        if (info.id == id)
            return info.kind;
    return std::nullopt;
}

} // namespace trimlab::render
