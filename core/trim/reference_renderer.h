#pragma once
/// \file
/// The exact CPU reference renderer (the oracle every GPU backend is tested against):
/// one ray per pixel centre through the shared Camera, every hit collected by a double
/// precision watertight BVH, sorted with walkOrder and decided by walkTrimRay — the same
/// rule, clip and winding semantics as the GPU, without fragment limits or float depth.

#include "core/image/rgba_image.h"
#include "core/scene/scene.h"
#include "core/trim/clip_plane.h"
#include "core/trim/ray_hit.h"
#include "core/trim/reference_diagnostics.h"
#include "core/trim/triangle_bvh.h"
#include "core/trim/trim_image.h"
#include "core/trim/trim_settings.h"
#include "core/trim/trim_walk.h"
#include "core/view/camera.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace trimlab {

/// Counts over one render.
struct ReferenceStats {
    std::uint64_t totalHits = 0; ///< hits with zNear <= t <= zFar, summed over pixels
    std::int32_t maxHitsPerPixel = 0;
    std::uint64_t coveredPixels = 0; ///< pixels that show a surface point
    double wallMs = 0.0;             ///< wall-clock time of render()
    unsigned threads = 0;            ///< worker threads actually used
};

struct ReferenceResult {
    TrimImage trim;
    /// Background kBackgroundColor where empty, else shadeTrimPoint with the smooth world
    /// normal at the hit and toViewer = −normalize(ray direction) (with applyHighlights
    /// for collisions and coplanar groups), or shadeCap for a cap; with transparency
    /// (TrimSettings::xray) the X-ray composite of every layer of the kept span
    /// (walkTrimLayers, compositeXray; the shown hit with its highlights, the others
    /// plain); channels are round(255·clamp(c, 0, 1)), alpha 255.
    RgbaImage color;
    ReferenceDiagnostics diagnostics;
    ReferenceStats stats;
};

/// Everything the reference knows about one pixel (for tests and debugging).
struct PixelTrace {
    PixelRay ray;
    std::vector<RayHit> hits; ///< zNear <= t <= zFar, sorted with walkOrder
    KeptSpan span;
    TrimWalk walk;
    TrimPixel pixel;
};

/// Decides one pixel from its sorted hits and kept span, in place of walkTrimRay (the
/// dynamic rules supply one). Sets `unresolved` when the pixel cannot be decided. Called
/// concurrently from several threads.
using RayWalker =
    std::function<TrimWalk(int x, int y, std::span<const RayHit> sortedHits, const KeptSpan& span, bool& unresolved)>;

class ReferenceRenderer {
public:
    /// Copies what it needs (world geometry, normals, the BVH); `scene` may die afterwards.
    explicit ReferenceRenderer(const Scene& scene);

    /// Renders width×height pixels. `threads` = 0 uses std::thread::hardware_concurrency().
    /// Preconditions (programmer errors, not checked): 0 < zNear < zFar and a valid
    /// camera (eye != target, up not parallel to the view direction). Width or height
    /// < 1 gives an empty (0×0) result.
    [[nodiscard]] ReferenceResult render(const Camera& camera, int width, int height, const TrimSettings& settings,
                                         unsigned threads = 0) const;
    /// The same with `walker` deciding every pixel (an unresolved pixel is empty with
    /// TrimPixel::unresolved set).
    [[nodiscard]] ReferenceResult render(const Camera& camera, int width, int height, const TrimSettings& settings,
                                         unsigned threads, const RayWalker& walker) const;

    /// The full decision for one pixel, as render() makes it.
    [[nodiscard]] PixelTrace tracePixel(const Camera& camera, int width, int height, int x, int y,
                                        const TrimSettings& settings) const;

    [[nodiscard]] const TriangleBvh& bvh() const { return m_bvh; }

private:
    struct ObjectGeometry {
        std::vector<glm::dvec3> positions; ///< world space
        std::vector<glm::dvec3> normals;   ///< world space, not normalised
        std::vector<glm::uvec3> triangles;
    };
    struct RowContext;

    void renderRow(RowContext& context, int y) const;
    /// Smooth-normal shading of the shown hit, with the pixel's highlights; a back face of
    /// an object in `carvedObjects` (csgSubtractedMask) is a carved wall.
    [[nodiscard]] glm::vec3 shadeHit(const RayHit& hit, const PixelRay& ray, const TrimPixel& pixel,
                                     std::uint32_t carvedObjects) const;
    /// Flat shading and world-space pattern of a cap.
    [[nodiscard]] glm::vec3 shadeCapPixel(const RowContext& context, const PixelRay& ray, const TrimWalk& walk) const;
    /// Unit smooth world normal at a hit (the face normal where the vertex normals cancel).
    [[nodiscard]] glm::dvec3 hitNormal(const RayHit& hit, const glm::dvec3& toViewer) const;
    /// The X-ray composite of the pixel (TransparencySettings).
    [[nodiscard]] glm::vec3 xrayPixel(RowContext& context, const PixelRay& ray, const KeptSpan& span,
                                      const TrimWalk& walk, const TrimPixel& pixel) const;

    TriangleBvh m_bvh;
    std::vector<ObjectGeometry> m_objects;
};

} // namespace trimlab
