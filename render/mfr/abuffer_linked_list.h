#pragma once
/// \file
/// AB_LL, the A-buffer with per-pixel linked lists (Yang et al., thesis 2.4.2, Figure
/// 2.6 b): one geometry pass pushes every fragment of the kept span on its pixel's list
/// (a head image, a node buffer, a buffer of next links and one global atomic node
/// counter; shaders/abuffer_list_store.frag); the resolve copies each list into registers,
/// sorts and walks it (shaders/abuffer_list_resolve.frag; lists longer than
/// kRegisterList are walked by selection instead).
///
/// Growth. The node buffer's size is not known before the frame. When the global counter
/// ends above the capacity, the frame lost fragments: the buffer grows to the counted
/// need plus 1/8 (so a slowly growing animation does not regrow every frame; never above
/// the driver's shader storage limit) and the frame is rendered again, so the method
/// never shows a frame with lost fragments. Each regrowth is counted
/// (MethodStats::regrowths, regrowthCount()). Reading the counter back waits for the GPU
/// once per frame. Unbounded; GpuMemoryError when the fragments do not fit one buffer.

#include "render/mfr/fragment_method.h"
#include "render/mfr/head_image.h"
#include "render/mfr/node_buffer.h"
#include "render/mfr/pixel_state.h"

#include <cstdint>

namespace trimlab::render {

class ABufferLinkedList final : public FragmentMethod {
public:
    /// Fragments a pixel's list may have to be sorted in registers.
    static constexpr int kRegisterList = 256;
    /// Capacity of the first frame, in fragments per pixel of that frame.
    static constexpr int kInitialFragmentsPerPixel = 4;

    explicit ABufferLinkedList(GlFunctions& gl);

    [[nodiscard]] FragmentMethodKind kind() const override { return FragmentMethodKind::ABufferLinkedList; }
    void render(TrimFrame& frame) override;
    [[nodiscard]] MethodStats stats() const override { return m_stats; }
    /// nullopt: the node buffer's size depends on the scene.
    [[nodiscard]] std::optional<std::size_t> estimateBytes(int width, int height,
                                                           const MethodParameters& parameters) const override;
    /// f(p) per pixel (every fragment is on its list).
    [[nodiscard]] std::optional<PixelOccupancy> readOccupancy() override { return m_state.readOccupancy(); }

    /// Replaces the node buffer by one of exactly `fragments` nodes (≥ 1), e.g. to give
    /// memory back after a heavy frame; the next frame grows it again if it needs more.
    /// Needs the GL context current. Throws GpuMemoryError.
    void setNodeCapacity(std::uint64_t fragments, const GlCapabilities& capabilities);
    /// Fragments the node buffer holds now (0 before the first frame).
    [[nodiscard]] std::uint64_t nodeCapacity() const { return m_nodes.capacity(); }
    /// Fragments the last frame stored (the global node counter).
    [[nodiscard]] std::uint64_t countedTotal() const { return m_countedTotal; }
    /// Regrowths since this object was created.
    [[nodiscard]] int regrowthCount() const { return m_regrowthCount; }

private:
    void allocate(const TrimFrame& frame);
    void grow(std::uint64_t needed, const TrimFrame& frame);
    std::uint64_t storePass(TrimFrame& frame);
    void resolvePass(TrimFrame& frame);

    GlFunctions& m_gl;
    PixelState m_state;
    HeadImage m_head;
    NodeBuffer m_nodes;
    NodeBuffer m_links;
    GlBuffer m_nodeCounter;
    std::uint64_t m_countedTotal = 0;
    int m_regrowthCount = 0;
    MethodStats m_stats;
};

} // namespace trimlab::render
