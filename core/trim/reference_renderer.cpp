#include "core/trim/reference_renderer.h"

#include "core/scene/world_geometry.h"
#include "core/trim/csg_expression.h"
#include "core/trim/transparency.h"
#include "core/trim/trim_shading.h"
#include "core/util/memory_budget.h"
#include "core/util/parallel_for.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace trimlab {

namespace {

constexpr int kRowsPerBlock = 4;

std::uint8_t toByte(float channel)
{
    return static_cast<std::uint8_t>(std::lround(255.0f * std::clamp(channel, 0.0f, 1.0f)));
}

} // namespace

/// Per-thread state: inputs, output images, scratch buffers and partial stats.
struct ReferenceRenderer::RowContext {
    const Camera& camera;
    int width;
    int height;
    const TrimSettings& settings;
    ClipSet clips;               ///< settings.clipSet(), built once
    std::uint32_t carvedObjects; ///< csgSubtractedMask of the CSG (0 without one)
    const RayWalker* walker;
    ReferenceResult& result;
    std::vector<RayHit> hits;
    std::vector<double> scratch;
    std::vector<WalkLayer> layers;       ///< transparency only
    std::vector<XrayFragment> fragments; ///< transparency only
    ReferenceStats stats;
};

ReferenceRenderer::ReferenceRenderer(const Scene& scene) : m_bvh(scene)
{
    m_objects.reserve(scene.objects.size());
    for (const SceneObject& object : scene.objects)
        m_objects.push_back({worldPositions(object), worldNormals(object), object.mesh.triangles});
}

PixelTrace ReferenceRenderer::tracePixel(const Camera& camera, int width, int height, int x, int y,
                                         const TrimSettings& settings) const
{
    PixelTrace trace;
    trace.ray = pixelRay(camera, width, height, x, y);
    m_bvh.intersectAll(trace.ray, camera.zNear, camera.zFar, trace.hits);
    std::sort(trace.hits.begin(), trace.hits.end(), walkOrder);
    trace.span = keptSpan(settings.clipSet(), trace.ray, camera.zNear, camera.zFar);
    trace.walk = walkTrimRay(trace.hits, trace.span, settings);
    trace.pixel = trimPixelFromWalk(trace.hits, trace.walk);
    return trace;
}

glm::dvec3 ReferenceRenderer::hitNormal(const RayHit& hit, const glm::dvec3& toViewer) const
{
    const ObjectGeometry& object = m_objects[std::size_t(hit.objectId)];
    const glm::uvec3 t = object.triangles[std::size_t(hit.primitiveId)];
    const double w = 1.0 - hit.u - hit.v;
    glm::dvec3 normal = w * object.normals[t[0]] + hit.u * object.normals[t[1]] + hit.v * object.normals[t[2]];
    if (!(glm::length(normal) > 0.0)) { // cancelling or missing vertex normals
        const glm::dvec3& a = object.positions[t[0]];
        normal = glm::cross(object.positions[t[1]] - a, object.positions[t[2]] - a);
    }
    const double length = glm::length(normal);
    return length > 0.0 ? normal / length : toViewer;
}

glm::vec3 ReferenceRenderer::shadeHit(const RayHit& hit, const PixelRay& ray, const TrimPixel& pixel,
                                      std::uint32_t carvedObjects) const
{
    const glm::dvec3 toViewer = -glm::normalize(ray.direction);
    const glm::dvec3 normal = hitNormal(hit, toViewer);
    const bool carved = hit.objectId >= 0 && hit.objectId < 32 && ((carvedObjects >> hit.objectId) & 1u) != 0u;
    const glm::vec3 shaded = shadeTrimPoint(hit.facing, normal, toViewer, carved);
    if (!pixel.collision && pixel.coplanarCount < 2)
        return shaded;
    const float lighting = kAmbient + (1.0f - kAmbient) * static_cast<float>(std::abs(glm::dot(normal, toViewer)));
    return applyHighlights(shaded, lighting, pixel.collision, pixel.coplanarCount);
}

glm::vec3 ReferenceRenderer::shadeCapPixel(const RowContext& context, const PixelRay& ray, const TrimWalk& walk) const
{
    const glm::dvec3 normal = glm::normalize(context.clips.planes[std::size_t(walk.capPlane)].normal);
    const glm::dvec3 point = ray.origin + walk.capDepth * ray.direction;
    return shadeCap(context.settings.cap, point, normal, -glm::normalize(ray.direction));
}

glm::vec3 ReferenceRenderer::xrayPixel(RowContext& context, const PixelRay& ray, const KeptSpan& span,
                                       const TrimWalk& walk, const TrimPixel& pixel) const
{
    walkTrimLayers(context.hits, walk, context.settings, context.layers);
    const double rayLength = glm::length(ray.direction);
    const glm::dvec3 toViewer = -ray.direction / rayLength;
    std::optional<XrayCap> cap;
    if (walk.capPlane >= 0) {
        const glm::dvec3 n = glm::normalize(context.clips.planes[std::size_t(walk.capPlane)].normal);
        cap = XrayCap{glm::dvec3(shadeCapPixel(context, ray, walk)), std::abs(glm::dot(n, toViewer))};
    }
    context.fragments.clear();
    for (const WalkLayer& layer : context.layers) {
        const RayHit& hit = context.hits[layer.index];
        const bool shown = std::ptrdiff_t(layer.index) == walk.shownIndex;
        const glm::vec3 color = shadeHit(hit, ray, shown ? pixel : TrimPixel{}, 0u); // X-ray: as its GLSL twin
        const double cosine = std::abs(glm::dot(hitNormal(hit, toViewer), toViewer));
        context.fragments.push_back(
            {hit.t * rayLength, layer.boundary, layer.interiorBefore, glm::dvec3(color), cosine});
    }
    return glm::vec3(compositeXray(context.settings.transparency, span.tStart * rayLength, cap, context.fragments,
                                   glm::dvec3(kBackgroundColor)));
}

void ReferenceRenderer::renderRow(RowContext& context, int y) const
{
    const Camera& camera = context.camera;
    for (int x = 0; x < context.width; ++x) {
        const PixelRay ray = pixelRay(camera, context.width, context.height, x, y);
        context.hits.clear();
        m_bvh.intersectAll(ray, camera.zNear, camera.zFar, context.hits);
        std::sort(context.hits.begin(), context.hits.end(), walkOrder);
        const KeptSpan span = keptSpan(context.clips, ray, camera.zNear, camera.zFar);
        bool unresolved = false;
        const TrimWalk walk = context.walker ? (*context.walker)(x, y, context.hits, span, unresolved)
                                             : walkTrimRay(context.hits, span, context.settings);
        TrimPixel pixel = trimPixelFromWalk(context.hits, walk);
        pixel.unresolved = unresolved;
        context.result.trim.at(x, y) = pixel;

        ReferenceDiagnostics& diagnostics = context.result.diagnostics;
        const std::size_t index = diagnostics.index(x, y);
        const auto hitCount = std::int32_t(context.hits.size());
        diagnostics.hitCount[index] = hitCount;
        diagnostics.depthMargin[index] = float(pixelDepthMargin(context.hits, span, walk, context.scratch));
        context.stats.totalHits += std::uint64_t(hitCount);
        context.stats.maxHitsPerPixel = std::max(context.stats.maxHitsPerPixel, hitCount);

        glm::vec3 color = kBackgroundColor;
        if (context.settings.xray())
            color = xrayPixel(context, ray, span, walk, pixel);
        if (pixel.isCap()) {
            if (!context.settings.xray())
                color = shadeCapPixel(context, ray, walk);
            ++context.stats.coveredPixels;
        } else if (pixel.covered()) {
            const RayHit& hit = context.hits[std::size_t(walk.shownIndex)];
            const ObjectGeometry& object = m_objects[std::size_t(hit.objectId)];
            const glm::uvec3 t = object.triangles[std::size_t(hit.primitiveId)];
            diagnostics.edgeDistancePx[index] =
                float(edgeDistancePixels(camera, context.width, context.height, x, y,
                                         {object.positions[t[0]], object.positions[t[1]], object.positions[t[2]]}));
            if (!context.settings.xray())
                color = shadeHit(hit, ray, pixel, context.carvedObjects);
            ++context.stats.coveredPixels;
        }
        std::uint8_t* rgba = context.result.color.at(x, y);
        rgba[0] = toByte(color.r);
        rgba[1] = toByte(color.g);
        rgba[2] = toByte(color.b);
        rgba[3] = 255;
    }
}

ReferenceResult ReferenceRenderer::render(const Camera& camera, int width, int height, const TrimSettings& settings,
                                          unsigned threads) const
{
    return render(camera, width, height, settings, threads, RayWalker{});
}

ReferenceResult ReferenceRenderer::render(const Camera& camera, int width, int height, const TrimSettings& settings,
                                          unsigned threads, const RayWalker& walker) const
{
    const auto start = std::chrono::steady_clock::now();
    ReferenceResult result;
    if (width < 1 || height < 1)
        return result;
    // Per pixel: the trim image, the colour and the diagnostics, all allocated up front.
    requireMemory(std::uint64_t(width) * std::uint64_t(height) * (sizeof(TrimPixel) + 4 + 3 * sizeof(float)),
                  "the CPU reference at " + std::to_string(width) + "x" + std::to_string(height),
                  "render a smaller image");
    result.trim = TrimImage(width, height);
    result.color = RgbaImage(width, height);
    result.diagnostics = ReferenceDiagnostics(width, height);

    // Blocks of rows on the shared pool (parallel_for.h): an exception in any block, an
    // allocation that failed included, reaches the caller after every worker stopped.
    const auto blockCount = std::size_t((height + kRowsPerBlock - 1) / kRowsPerBlock);
    threads = effectiveThreadCount(threads, blockCount);
    std::vector<ReferenceStats> partial(blockCount);
    const auto renderBlock = [&](std::size_t block) {
        RowContext context{camera,
                           width,
                           height,
                           settings,
                           settings.clipSet(),
                           csgSubtractedMask(settings.csg.expression),
                           walker ? &walker : nullptr,
                           result,
                           {},
                           {},
                           {},
                           {},
                           {}};
        const int rowEnd = std::min(height, int(block + 1) * kRowsPerBlock);
        for (int y = int(block) * kRowsPerBlock; y < rowEnd; ++y)
            renderRow(context, y);
        partial[block] = context.stats;
    };
    parallelFor(blockCount, threads, renderBlock);

    for (const ReferenceStats& s : partial) {
        result.stats.totalHits += s.totalHits;
        result.stats.maxHitsPerPixel = std::max(result.stats.maxHitsPerPixel, s.maxHitsPerPixel);
        result.stats.coveredPixels += s.coveredPixels;
    }
    result.stats.threads = threads;
    result.stats.wallMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return result;
}

} // namespace trimlab
