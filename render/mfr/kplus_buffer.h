#pragma once
/// \file
/// The k⁺-buffer of thesis chapter 7 with the max-array (K⁺B-Array): per pixel, the k
/// nearest fragments of the kept span, captured unsorted under a per-pixel spin-lock with
/// fragment culling against the current maximum (layer 0), sorted in the resolve pass.
/// Besides the fragments it keeps, per pixel, the exact winding index at the span start
/// and an overflow flag (more than k fragments arrived). Shaders:
/// kplus_clear.comp, kplus_store.frag, trim_resolve.frag.

#include "gl/gl_functions.h"
#include "gl/gl_objects.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace trimlab::render {

class ShaderLibrary;

/// Per-pixel occupancy of the buffer after a store pass, row 0 at the top: the number of
/// fragments held (<= k) and whether more than k arrived. For diagnostics and tests.
struct KPlusOccupancy {
    int width = 0;
    int height = 0;
    std::vector<std::uint32_t> held;
    std::vector<std::uint8_t> overflowed;
};

class KPlusBuffer {
public:
    /// Largest k the resolve pass supports (its per-pixel register array).
    static constexpr int kMaxK = 128;

    KPlusBuffer(GlFunctions& gl, ShaderLibrary& shaders);

    /// Allocates for a width×height viewport and capacity k (1..kMaxK); reallocates only
    /// on change. Throws GpuMemoryError (with the sizes involved) when it does not fit.
    void allocate(int width, int height, int k);

    /// Clear pass: counters, locks, winding and overflow flags to zero.
    void clear();
    /// Binds the image units for the store pass (read/write).
    void bindImages();

    /// Reads the counters and overflow flags back (waits for the GPU).
    [[nodiscard]] KPlusOccupancy readOccupancy();

    [[nodiscard]] int k() const { return m_k; }
    [[nodiscard]] int width() const { return m_width; }
    [[nodiscard]] int height() const { return m_height; }
    /// Bytes of GPU memory held: the fragment layers plus the four per-pixel images.
    [[nodiscard]] std::size_t memoryBytes() const;
    /// Bytes a width×height buffer with capacity k needs.
    [[nodiscard]] static std::size_t requiredBytes(int width, int height, int k);

private:
    GlFunctions& m_gl;
    ShaderLibrary& m_shaders;
    GlTexture m_counter;
    GlTexture m_semaphore;
    GlTexture m_winding;
    GlTexture m_overflow;
    GlTexture m_fragments;
    int m_width = 0;
    int m_height = 0;
    int m_k = 0;
};

} // namespace trimlab::render
