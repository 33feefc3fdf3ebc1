#pragma once
/// \file
/// K⁺B-SB, the memory-aware k⁺-buffer of thesis 7.1.3 (Algorithm 7.8 with COUNT and
/// REFERENCING): the S-buffer's count pass and memory referencing
/// (mfr/memory_referencing.h) give each pixel a region of exactly min(f(p), k) nodes in
/// one node buffer; the store pass is the k⁺-buffer's (shaders/kplus_store.frag with
/// KPLUS_NODE_REGION): culling against the region's maximum, then insertion under the
/// per-pixel lock (spin-lock or fragment shader interlock) into a max-array, or a
/// max-heap where f(p) > k and k > 16. The resolve is the k⁺-buffer's too.
/// Bounded by k: a pixel with f(p) > k keeps its k nearest fragments and is flagged
/// overflowed (known exactly from the count); it is unresolved only when its trim point
/// lies beyond them.

#include "render/mfr/fragment_method.h"
#include "render/mfr/head_image.h"
#include "render/mfr/kplus_buffer.h"
#include "render/mfr/memory_referencing.h"
#include "render/mfr/node_buffer.h"
#include "render/mfr/pixel_state.h"

#include <cstdint>

namespace trimlab::render {

class KPlusSBuffer final : public FragmentMethod {
public:
    explicit KPlusSBuffer(GlFunctions& gl);

    [[nodiscard]] FragmentMethodKind kind() const override { return FragmentMethodKind::KPlusSBuffer; }
    void render(TrimFrame& frame) override;
    [[nodiscard]] MethodStats stats() const override { return m_stats; }
    /// nullopt: the allocation depends on the scene (at most that of the k⁺-buffer).
    [[nodiscard]] std::optional<std::size_t> estimateBytes(int width, int height,
                                                           const MethodParameters& parameters) const override;
    /// Fragments held per pixel, min(f(p), k), and the pixels with f(p) > k.
    [[nodiscard]] std::optional<PixelOccupancy> readOccupancy() override { return m_state.readOccupancy(); }

    /// Σ_p min(f(p), k) of the last frame: the node buffer's used (and bound) size.
    [[nodiscard]] std::uint64_t countedTotal() const { return m_countedTotal; }
    /// Nodes the buffer can hold: the largest total so far (grown to exactly the counted
    /// total when a frame needs more, never shrunk).
    [[nodiscard]] std::uint64_t nodeCapacity() const { return m_nodes.capacity(); }

private:
    void storePass(TrimFrame& frame, KPlusLock lock);
    void resolvePass(TrimFrame& frame);

    GlFunctions& m_gl;
    PixelState m_state;
    HeadImage m_head;
    MemoryReferencing m_referencing;
    NodeBuffer m_nodes;
    std::uint64_t m_countedTotal = 0;
    int m_k = 0;
    MethodStats m_stats;
};

} // namespace trimlab::render
