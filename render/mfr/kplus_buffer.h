#pragma once
/// \file
/// The k⁺-buffer of thesis chapter 7 (K⁺B-Array and K⁺B-Heap): per pixel, the k nearest
/// fragments of the kept span, captured unsorted in one geometry pass under a per-pixel
/// lock with fragment culling against the current maximum, sorted in the resolve pass
/// (insertion sort up to 16, shell sort above). The lock is a bounded spin-lock on
/// imageAtomicExchange, or fragment shader interlock where the driver offers it.
/// Besides the fragments, the exact winding index at the span start and an overflow flag
/// per pixel (PixelState). Shaders: kplus_store.frag, kplus_resolve.frag.

#include "render/gl/gl_objects.h"
#include "render/mfr/fragment_method.h"
#include "render/mfr/pixel_state.h"
#include "render/mfr/slot_array.h"

#include <QStringList>

namespace trimlab::render {

struct GlCapabilities;

/// The critical-section mechanism the store pass uses on this driver. Only the ARB
/// interlock is used: NVIDIA and Intel drivers that have the NV/INTEL forerunners expose
/// it too, and glslangValidator cannot check the older extensions.
enum class KPlusLock { SpinLock, InterlockArb };

/// Picks interlock where the context has it (and the user allows it), else the spin-lock.
[[nodiscard]] KPlusLock chooseKPlusLock(const GlCapabilities& capabilities, bool allowInterlock);
/// The store shader's defines for `lock` and the data structure.
[[nodiscard]] QStringList kplusStoreDefines(KPlusLock lock, bool heap);

class KPlusBuffer final : public FragmentMethod {
public:
    /// `heap`: the max-heap variant (K⁺B-Heap), else the max-array.
    KPlusBuffer(GlFunctions& gl, bool heap);

    [[nodiscard]] FragmentMethodKind kind() const override;
    void render(TrimFrame& frame) override;
    [[nodiscard]] MethodStats stats() const override { return m_stats; }
    [[nodiscard]] std::optional<std::size_t> estimateBytes(int width, int height,
                                                           const MethodParameters& parameters) const override;

    /// Per-pixel fragments held (≤ k) and overflow flags of the last frame.
    [[nodiscard]] std::optional<PixelOccupancy> readOccupancy() override { return m_state.readOccupancy(); }

private:
    void storePass(TrimFrame& frame, KPlusLock lock);
    void resolvePass(TrimFrame& frame);

    GlFunctions& m_gl;
    bool m_heap;
    PixelState m_state;
    SlotArray m_slots;
    MethodStats m_stats;
};

} // namespace trimlab::render
