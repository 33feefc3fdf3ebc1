#include "render/frame_policy.h"

#include "render/memory_fallback.h"

namespace trimlab::render {

namespace {

std::string displayName(FragmentMethodKind method)
{
    return std::string(methodInfo(method).displayName);
}

} // namespace

void FramePolicy::choose(FragmentMethodKind method)
{
    m_chosen = method;
    reset();
}

void FramePolicy::reset()
{
    m_fallback.reset();
    m_cpuStill = false;
    m_stopped = false;
}

FrameRecovery FramePolicy::outOfMemory(const std::string& reason, const FrameDemands& demands)
{
    const std::optional<FragmentMethodKind> next =
        memoryFallbackAfter(effectiveMethod(), demands.dynamicRules, demands.inspection);
    if (next) {
        m_fallback = next;
        return {FrameRecovery::Action::OtherMethod,
                reason + " Showing " + displayName(*next) + " instead; choose another method or size to try again."};
    }
    if (demands.dynamicRules) // the CPU still knows only the static rule
        return {FrameRecovery::Action::Refuse,
                reason +
                    " No GPU method with the dynamic rules fits: lower the image size or raise the memory budget."};
    m_cpuStill = true;
    return {FrameRecovery::Action::CpuStill,
            reason + " No GPU method fits this view: showing the CPU reference as a still image (it re-renders after "
                     "each change, which takes a moment)."};
}

FrameRecovery FramePolicy::contextLost(const std::string& reason, const FrameDemands& demands)
{
    ++m_lossesInARow;
    if (m_lossesInARow >= kResetsBeforeFallback && !m_cpuStill)
        return blameMethod(reason, demands);
    return {FrameRecovery::Action::Recreate,
            reason + " TrimLab re-created the OpenGL context and uploaded the scene again; nothing of your work was "
                     "lost."};
}

// Resets in a row: the method's own frames are the likely cause (a watchdog timeout), so
// the next method of the memory fallback chain takes over. Under the dynamic rules with
// none left, rendering stops until the user changes something, rather than resetting the
// GPU again every frame.
FrameRecovery FramePolicy::blameMethod(const std::string& reason, const FrameDemands& demands)
{
    m_lossesInARow = 0;
    const std::string method = displayName(effectiveMethod());
    const bool methodLeft =
        memoryFallbackAfter(effectiveMethod(), demands.dynamicRules, demands.inspection).has_value();
    if (methodLeft || !demands.dynamicRules)
        return outOfMemory(reason + " It happened again while rendering with " + method +
                               ", so TrimLab re-created the OpenGL context and no longer uses that method here.",
                           demands);
    m_stopped = true;
    return {FrameRecovery::Action::Stop,
            reason + " It keeps happening under the dynamic rules with " + method +
                ", the leanest method that runs them, so TrimLab stopped rendering. Lower the view size, switch to "
                "the static rule or choose a method to try again."};
}

} // namespace trimlab::render
