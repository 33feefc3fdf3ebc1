#pragma once
/// \file
/// The S-buffer of thesis chapter 5 (SB): an A-buffer that holds every fragment of every
/// pixel's kept span in a node buffer of exactly the counted size. Two geometry passes:
/// the count pass and, after memory referencing with S shared counters
/// (mfr/memory_referencing.h), the store pass that writes each fragment to its pixel's
/// next node (shaders/sbuffer_store.frag). The resolve (shaders/sbuffer_resolve.frag)
/// sorts a pixel's region in registers up to kRegisterList fragments and, for longer
/// lists, in place in the node buffer; it walks them with the shared trim walk. Unbounded:
/// it never loses a fragment; a frame whose fragments do not fit one shader storage
/// buffer throws GpuMemoryError.

#include "render/mfr/fragment_method.h"
#include "render/mfr/head_image.h"
#include "render/mfr/memory_referencing.h"
#include "render/mfr/node_buffer.h"
#include "render/mfr/pixel_state.h"

#include <cstdint>

namespace trimlab::render {

class SBuffer final : public FragmentMethod {
public:
    /// Fragments a pixel's list may have to be sorted in registers (the resolve's array,
    /// 2 KB per invocation); longer lists are sorted in the node buffer.
    static constexpr int kRegisterList = 256;

    explicit SBuffer(GlFunctions& gl);

    [[nodiscard]] FragmentMethodKind kind() const override { return FragmentMethodKind::SBuffer; }
    void render(TrimFrame& frame) override;
    [[nodiscard]] MethodStats stats() const override { return m_stats; }
    /// nullopt: the S-buffer's memory depends on the scene.
    [[nodiscard]] std::optional<std::size_t> estimateBytes(int width, int height,
                                                           const MethodParameters& parameters) const override;
    /// f(p) per pixel (every fragment of the kept span is held); no pixel overflows.
    [[nodiscard]] std::optional<PixelOccupancy> readOccupancy() override { return m_state.readOccupancy(); }

    /// Fragments the last frame counted: the node buffer's used (and bound) size.
    [[nodiscard]] std::uint64_t countedTotal() const { return m_countedTotal; }
    /// Fragments the node buffer can hold: the largest total counted so far (it grows to
    /// exactly the counted total when a frame needs more, and never shrinks).
    [[nodiscard]] std::uint64_t nodeCapacity() const { return m_nodes.capacity(); }

private:
    void storePass(TrimFrame& frame);
    void resolvePass(TrimFrame& frame);

    GlFunctions& m_gl;
    PixelState m_state;
    HeadImage m_head;
    MemoryReferencing m_referencing;
    NodeBuffer m_nodes;
    std::uint64_t m_countedTotal = 0;
    MethodStats m_stats;
};

} // namespace trimlab::render
