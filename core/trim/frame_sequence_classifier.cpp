#include "core/trim/frame_sequence_classifier.h"

#include "core/trim/dynamic_frame_scene.h"
#include "core/trim/dynamic_walk.h"
#include "core/trim/triangle_bvh.h"
#include "core/util/parallel_for.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace trimlab {

namespace {

Scene frameScene(const std::vector<glm::uvec3>& triangles, const std::vector<glm::vec3>& positions)
{
    Scene scene;
    scene.objects.emplace_back();
    scene.objects.back().mesh.triangles = triangles;
    scene.objects.back().mesh.positions = positions;
    return scene;
}

/// The sorted hits of pixel (x, y) over the camera's depth range.
void pixelHits(const TriangleBvh& bvh, const Camera& camera, int width, int height, int x, int y,
               std::vector<RayHit>& hits)
{
    hits.clear();
    bvh.intersectAll(pixelRay(camera, width, height, x, y), camera.zNear, camera.zFar, hits);
    std::sort(hits.begin(), hits.end(), walkOrder);
}

} // namespace

FrameSequenceClassifier::FrameSequenceClassifier(std::vector<glm::uvec3> triangles, const Camera& camera, int width,
                                                 int height, SequenceRule rule, unsigned threads)
    : m_triangles(std::move(triangles)),
      m_camera(camera),
      m_width(std::max(width, 0)),
      m_height(std::max(height, 0)),
      m_rule(rule),
      m_threads(threads)
{
}

FrameFragments FrameSequenceClassifier::next(const std::vector<glm::vec3>& positions)
{
    if (m_framesSeen > 0 && positions.size() != m_first.size())
        throw std::invalid_argument("frame " + std::to_string(m_framesSeen) + " has " +
                                    std::to_string(positions.size()) + " vertices, the first frame " +
                                    std::to_string(m_first.size()));
    FrameFragments frame;
    if (m_framesSeen == 0) {
        m_first = positions;
        frame = classifyStatic(positions);
    } else if (!m_rule.dynamicRule) {
        frame = classifyStatic(positions);
    } else {
        const bool previous = m_rule.reference == SequenceReference::Previous;
        frame = classifyDynamic(previous ? m_previous : m_first, positions);
    }
    m_previous = positions;
    ++m_framesSeen;
    return frame;
}

FrameFragments FrameSequenceClassifier::emptyFrame() const
{
    FrameFragments frame;
    frame.width = m_width;
    frame.height = m_height;
    frame.pixels.resize(std::size_t(m_width) * std::size_t(m_height));
    frame.unresolved.assign(frame.pixels.size(), 0);
    return frame;
}

FrameFragments FrameSequenceClassifier::classifyStatic(const std::vector<glm::vec3>& positions) const
{
    FrameFragments frame = emptyFrame();
    const TriangleBvh bvh(frameScene(m_triangles, positions));
    parallelFor(std::size_t(m_height), m_threads, [&](std::size_t row) {
        std::vector<RayHit> hits;
        for (int x = 0; x < m_width; ++x) {
            pixelHits(bvh, m_camera, m_width, m_height, x, int(row), hits);
            frame.pixels[row * std::size_t(m_width) + std::size_t(x)] = staticRayFragments(hits, m_rule.staticRule);
        }
    });
    return frame;
}

// One set from `reference` to `current`. Against the previous frame, the reference is
// classified by the characterization the last call left (the base rule for the first
// set), and this frame's characterization is kept for the next.
FrameFragments FrameSequenceClassifier::classifyDynamic(const std::vector<glm::vec3>& reference,
                                                        const std::vector<glm::vec3>& current)
{
    FrameFragments frame = emptyFrame();
    const DynamicFrameScene scene = makeDynamicFrameScene(m_triangles, reference, current);
    const TriangleBvh bvh(scene.scene);
    const bool carry = m_rule.reference == SequenceReference::Previous;
    const bool carried = carry && !m_characterizations.empty();
    std::vector<PartitionCharacterization> characterizations(frame.pixels.size());
    parallelFor(std::size_t(m_height), m_threads, [&](std::size_t row) {
        std::vector<RayHit> hits;
        for (int x = 0; x < m_width; ++x) {
            const std::size_t pixel = row * std::size_t(m_width) + std::size_t(x);
            pixelHits(bvh, m_camera, m_width, m_height, x, int(row), hits);
            const ReferenceClassification classification{carried ? &m_characterizations[pixel] : nullptr,
                                                         m_rule.staticRule};
            characterizations[pixel] = characterizeDynamicRay(hits, *m_rule.dynamicRule, classification);
            frame.pixels[pixel] = dynamicRayFragments(hits, scene, characterizations[pixel]);
            frame.unresolved[pixel] = characterizations[pixel].overflowed ? 1 : 0;
        }
    });
    if (carry)
        m_characterizations = std::move(characterizations);
    return frame;
}

} // namespace trimlab
