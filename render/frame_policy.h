#pragma once
/// \file
/// Which method renders the interactive view's next frame, and what a failed frame
/// changes — the policy of the viewport (ui/viewport/viewport_widget.h), apart from the
/// widget that paints, so that it is tested without one (render.frame_policy):
/// - Out of GPU memory (GpuMemoryError): the next method of the memory fallback chain
///   (memory_fallback.h) renders instead; with none left the view shows the CPU
///   reference as a still image — except under the dynamic rules, which the CPU still
///   does not know: then the frame is refused with what to change.
/// - A GPU reset (render/gl/context_reset.h): the view re-creates its context and renders
///   the same frame. A second reset before any frame succeeded blames the method (a
///   frame that trips the driver's watchdog): the next method of the chain takes over as
///   for memory; under the dynamic rules, where the chain ends at the S-buffer, the view
///   then stops rendering until something changes, rather than resetting the GPU every
///   frame.
/// Choosing a method, its parameters, the scene or the view size goes back to the chosen
/// method (reset()); a new dynamic chain lifts a stop (clearStop()).
///
/// Messages are whole sentences for the user: the failure's own reason, then what the
/// view does about it.

#include "render/mfr/fragment_method.h"

#include <optional>
#include <string>

namespace trimlab::render {

/// What the frame to render needs of a method.
struct FrameDemands {
    bool dynamicRules = false; ///< the dynamic rules' chain (no peeling, no CPU still)
    bool inspection = false;   ///< CSG or highlights (needsInspectionMethod)
};

/// What the view does after a failed frame.
struct FrameRecovery {
    enum class Action {
        OtherMethod, ///< render again with effectiveMethod(); `message` is a notice
        CpuStill,    ///< show the CPU reference as a still image; `message` is a notice
        Refuse,      ///< no method fits: `message` is the frame's error
        Recreate,    ///< re-create the OpenGL context, render the same frame; a notice
        Stop,        ///< re-create the context but render nothing until a change; an error
    };
    Action action = Action::OtherMethod;
    std::string message;
};

class FramePolicy {
public:
    /// The method the user chose; back to it from any fallback (as reset()).
    void choose(FragmentMethodKind method);
    [[nodiscard]] FragmentMethodKind chosenMethod() const { return m_chosen; }
    /// The method frames use: the chosen one, or the fallback that replaced it.
    [[nodiscard]] FragmentMethodKind effectiveMethod() const { return m_fallback.value_or(m_chosen); }
    /// True while no GPU method fits and the view shows the CPU reference.
    [[nodiscard]] bool showsCpuStill() const { return m_cpuStill; }
    /// True after resets in a row left no method: no frame until reset() or clearStop().
    [[nodiscard]] bool stopped() const { return m_stopped; }

    /// Something changed that may let the chosen method fit again (its parameters, the
    /// scene, the view size): the chosen method, no CPU still, no stop.
    void reset();
    /// A new dynamic chain: rendering may be tried again (the fallback stays).
    void clearStop() { m_stopped = false; }

    /// The frame ran out of GPU memory for `reason` (GpuMemoryError::what()).
    [[nodiscard]] FrameRecovery outOfMemory(const std::string& reason, const FrameDemands& demands);
    /// The GPU reset while the frame rendered; `reason` says what the driver reported.
    [[nodiscard]] FrameRecovery contextLost(const std::string& reason, const FrameDemands& demands);
    /// A frame succeeded: later resets are no longer "in a row".
    void frameRendered() { m_lossesInARow = 0; }

    /// GPU resets in a row (no frame between) after which the method is blamed.
    static constexpr int kResetsBeforeFallback = 2;

private:
    [[nodiscard]] FrameRecovery blameMethod(const std::string& reason, const FrameDemands& demands);

    FragmentMethodKind m_chosen = FragmentMethodKind::KPlusArray;
    std::optional<FragmentMethodKind> m_fallback;
    bool m_cpuStill = false;
    bool m_stopped = false;
    int m_lossesInARow = 0;
};

} // namespace trimlab::render
