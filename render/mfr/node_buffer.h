#pragma once
/// \file
/// A shader storage buffer of per-fragment records for the node-buffer methods (S-buffer,
/// K⁺B-SB, AB_LL): `bytesPerNode` bytes per fragment (8 for a packed fragment,
/// shaders/common/fragment_pack.glsl; 4 for a linked list's next link). It only grows,
/// and never beyond the driver's GL_MAX_SHADER_STORAGE_BLOCK_SIZE (128 MB on llvmpipe):
/// a frame that needs more throws GpuMemoryError saying what to do instead. A user memory
/// budget (MethodParameters::memoryBudgetBytes) lowers that limit further.

#include "render/gl/gl_functions.h"
#include "render/gl/gl_objects.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace trimlab::render {

struct GlCapabilities;

class NodeBuffer {
public:
    /// `what` names the buffer in error messages, e.g. "S-buffer node buffer".
    NodeBuffer(GlFunctions& gl, std::size_t bytesPerNode, std::string what);

    /// The most nodes one shader storage block can hold on this driver, and within
    /// `budgetBytes` when that is not 0.
    [[nodiscard]] std::uint64_t maxNodes(const GlCapabilities& capabilities, std::size_t budgetBytes = 0) const;

    /// Makes room for `nodes` (≥ 0) nodes: reallocates to exactly max(nodes, 1) when the
    /// capacity is smaller, else keeps the buffer (its contents are never kept). Throws
    /// GpuMemoryError when `nodes` exceed maxNodes (the message gives the fragments, the
    /// MB, the limit, and suggests a smaller image or a bounded method) or the driver runs
    /// out of memory. `width`×`height` only go into that message.
    void reserve(std::uint64_t nodes, const GlCapabilities& capabilities, int width, int height,
                 std::size_t budgetBytes = 0);
    /// Releases the storage and allocates exactly max(nodes, 1) nodes; throws like
    /// reserve() when nodes > maxNodes(capabilities, budgetBytes).
    void reallocate(std::uint64_t nodes, const GlCapabilities& capabilities, int width, int height,
                    std::size_t budgetBytes = 0);

    /// Binds the first max(nodes, 1) nodes (nodes ≤ capacity) to shader storage `binding`.
    void bind(GLuint binding, std::uint64_t nodes);

    [[nodiscard]] std::uint64_t capacity() const { return m_capacity; }
    [[nodiscard]] std::size_t bytes() const { return std::size_t(m_capacity) * m_bytesPerNode; }

private:
    GlFunctions& m_gl;
    std::size_t m_bytesPerNode;
    std::string m_what;
    GlBuffer m_buffer;
    std::uint64_t m_capacity = 0;
};

} // namespace trimlab::render
