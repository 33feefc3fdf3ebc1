#pragma once
/// \file
/// The one interface every multi-fragment method implements (thesis chapters 5–8): given
/// the scene, camera and trim settings, produce per pixel the winding index at the start
/// of the kept span and the first trim fragment (depth, facing, primitive and object id)
/// in the render target. Methods differ only in how they capture and order fragments;
/// the trim walk (shaders/common/trim_walk.glsl) and the output are shared.

#include "render/gl/gl_functions.h"
#include "render/mfr/pixel_state.h"

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

namespace trimlab::render {

struct TrimFrame;

enum class FragmentMethodKind {
    KPlusArray,        ///< k⁺-buffer, max-array (chapter 7)
    KPlusHeap,         ///< k⁺-buffer, max-heap (Algorithm 7.7)
    KPlusSBuffer,      ///< K⁺B-SB: precise allocation bounded by k (7.1.3)
    SBuffer,           ///< S-buffer (chapter 5)
    ABufferFixed,      ///< AB_FP: fixed-size per-pixel arrays
    ABufferLinkedList, ///< AB_LL: per-pixel linked lists
    PeelingF2B,        ///< front-to-back depth peeling
    PeelingDual,       ///< dual depth peeling
    TwoPass,           ///< sort-independent two-pass classification (Algorithms 8.9, 8.10)
};

/// What a method is and which parameters it uses.
struct MethodInfo {
    FragmentMethodKind kind;
    std::string_view id;          ///< stable command-line / settings name, e.g. "kplus-array"
    std::string_view displayName; ///< e.g. "k⁺-buffer (max-array)"
    bool bounded;                 ///< capacity-limited: may overflow and report unresolved pixels
    bool usesK;
    bool usesSharedCounters;
    /// Stores fragments and walks them in one resolve, so it can run the dynamic rules'
    /// walk (the peeling methods and the two-pass method cannot: they never hold a
    /// pixel's reference and current fragments together).
    bool dynamicRules;
    /// Its resolve walks all of a pixel's fragments in one invocation, so it can carry the
    /// per-object windings of CSG and collision highlighting, count coplanar groups and
    /// composite transparency (X-ray) layers (the buffer methods). Clipping sets and
    /// capping work with every method.
    bool inspection;
    /// Reads a result of its own frame back before the frame ends — the S-buffer family's
    /// fragment total (it sizes the node buffer), the linked lists' node count (it grows
    /// them), the peeling methods' occlusion query (it ends the peeling) — so its frames
    /// make the CPU wait for the GPU even when frames are pipelined.
    bool waitsMidFrame;
};

/// Every method, in menu order. Only those with an implementation are listed.
[[nodiscard]] const std::vector<MethodInfo>& fragmentMethods();
[[nodiscard]] const MethodInfo& methodInfo(FragmentMethodKind kind);
[[nodiscard]] std::optional<FragmentMethodKind> parseFragmentMethod(std::string_view id);

/// User-chosen parameters (a method ignores those it does not use).
struct MethodParameters {
    int k = 16;                  ///< slots per pixel (k⁺-buffer variants, AB_FP)
    int sharedCounters = 1024;   ///< S: shared counters of the S-buffer's memory referencing
    bool allowInterlock = true;  ///< use fragment shader interlock where the driver has it
    int maxPeelingPasses = 1024; ///< safety bound for the peeling methods
    /// The user's GPU memory budget for the method's storage, in bytes (0: no budget, only
    /// the driver's limits). A frame whose storage would exceed it throws GpuMemoryError
    /// before allocating (TrimRenderer checks the methods with an estimate; the node
    /// buffers of the counted methods check when they grow). The render target and the
    /// scene buffers come on top (FrameStats::bufferMegabytes shows the total).
    std::size_t memoryBudgetBytes = 0;

    /// The limits of the user's choices; their ranges, defaults and help are the rows of
    /// method_parameter_table.h, which read these.
    static constexpr int kMaxK = 128;
    static constexpr int kMaxSharedCounters = 1 << 20;        ///< the prefix pass is linear in S
    static constexpr int kMaxMemoryBudgetMegabytes = 1 << 20; ///< 1 TB: no real limit

    friend bool operator==(const MethodParameters&, const MethodParameters&) = default;
};

/// What a frame cost the method beyond the shared frame counters.
struct MethodStats {
    int geometryPasses = 0;   ///< times the scene was rasterised
    int fullscreenPasses = 0; ///< resolve / referencing passes
    std::size_t bytes = 0;    ///< GPU memory the method holds
    bool interlock = false;   ///< the critical section used fragment shader interlock
    int regrowths = 0;        ///< times the storage grew and the frame was rendered again (AB_LL)
    bool usesLock = false;    ///< the method has a per-pixel critical section (k⁺-buffer family)
};

/// "spin-lock", "fragment shader interlock" or "none" for a frame's stats.
[[nodiscard]] const char* lockDescription(const MethodStats& stats);

class FragmentMethod {
public:
    virtual ~FragmentMethod() = default;
    [[nodiscard]] virtual FragmentMethodKind kind() const = 0;
    /// Renders `frame` into its render target: color and id attachments, plus the frame
    /// counters. Throws GpuMemoryError when its storage cannot be allocated.
    virtual void render(TrimFrame& frame) = 0;
    [[nodiscard]] virtual MethodStats stats() const = 0;
    /// Bytes a frame of width×height with `parameters` would hold, before allocating it
    /// (for the UI's memory estimate); nullopt when it depends on the scene (counted methods).
    [[nodiscard]] virtual std::optional<std::size_t> estimateBytes(int width, int height,
                                                                   const MethodParameters& parameters) const = 0;
    /// Per-pixel fragment counts of the last frame, for methods that keep them.
    [[nodiscard]] virtual std::optional<PixelOccupancy> readOccupancy() { return std::nullopt; }
};

} // namespace trimlab::render
