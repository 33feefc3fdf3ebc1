#include "render/viewport_renderer.h"

#include "render/frame/gpu_scene.h"
#include "render/gl/context_reset.h"
#include "render/gl/gl_error.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace trimlab::render {

ViewportRenderer::ViewportRenderer(std::shared_ptr<ShownContent> content)
    : m_content(std::move(content)),
      m_subscription(m_content->subscribe([this](ShownLayer layer) { contentChanged(layer); }))
{
}

ViewportRenderer::~ViewportRenderer() = default;

// What a change means for the frame policy and the frame record, at once: the widget
// asks the policy which path to paint before the next frame syncs anything.
void ViewportRenderer::contentChanged(ShownLayer layer)
{
    if (layer == ShownLayer::Geometry && m_content->meshVersion() != m_meshesSeen) {
        m_meshesSeen = m_content->meshVersion();
        forgetLastFrame();
        m_policy.reset(); // another scene: back to the chosen method
    }
    if (layer == ShownLayer::Chain) {
        const ShownChain* chain = m_content->chain();
        const std::uint64_t id = chain ? chain->id : 0;
        if (id != m_chainSeen) {
            m_chainSeen = id;
            m_policy.clearStop(); // other rules: worth trying again after resets in a row
        }
    }
}

void ViewportRenderer::setMethod(FragmentMethodKind method)
{
    m_policy.choose(method);
}

void ViewportRenderer::setMethodParameters(const MethodParameters& parameters)
{
    m_parameters = parameters;
    m_parameters.k = std::clamp(parameters.k, 1, MethodParameters::kMaxK);
    m_parameters.sharedCounters = std::max(parameters.sharedCounters, 1);
    m_policy.reset();
}

void ViewportRenderer::initialize(QOpenGLContext& context)
{
    m_uploaded = {};
    m_renderer = std::make_unique<TrimRenderer>(context);
    m_renderer->setPipelined(true);
    applyMethod();
}

void ViewportRenderer::release()
{
    m_issued.clear();  // their results go with the context
    m_dynamic.reset(); // its GL objects go first: it holds a reference to the renderer
    m_gpuPose.evaluator.reset();
    m_renderer.reset();
    m_uploaded = {}; // a new context gets every layer again
}

void ViewportRenderer::applyMethod()
{
    m_renderer->setMethod(m_policy.effectiveMethod());
    m_renderer->setParameters(m_parameters);
}

FrameDemands ViewportRenderer::frameDemands() const
{
    return {dynamicFrames(), needsInspectionMethod(m_settings)};
}

// Out of GPU memory (checked before allocating, or a failed allocation): the next method
// of the fallback chain renders the frame; none left → the CPU still (frame_policy.h).
bool ViewportRenderer::render(const Camera& camera, QSize size, GLuint framebuffer, const Notify& notify)
{
    for (;;) {
        try {
            renderFrame(camera, size, framebuffer);
            m_policy.frameRendered();
            return true;
        } catch (const GpuMemoryError& e) {
            const FrameRecovery recovery = m_policy.outOfMemory(e.what(), frameDemands());
            forgetLastFrame();
            if (recovery.action == FrameRecovery::Action::Refuse)
                throw GpuMemoryError(recovery.message);
            notify(recovery.message);
            if (recovery.action == FrameRecovery::Action::CpuStill)
                return false;
        }
    }
}

FrameRecovery ViewportRenderer::contextLost(const std::string& reason)
{
    forgetLastFrame();
    return m_policy.contextLost(reason, frameDemands());
}

// The scene itself when its meshes changed or the context is new (the upload carries the
// model matrices and the scene's own positions, without colours); else the matrices when
// an object moved.
void ViewportRenderer::syncGeometry()
{
    const ShownContent& content = *m_content;
    if (m_uploaded.meshes != content.meshVersion()) {
        m_renderer->setScene(*content.scene());
        m_uploaded.meshes = content.meshVersion();
        m_uploaded.geometry = content.version(ShownLayer::Geometry);
        m_uploaded.posed = false;
        m_uploaded.pose = content.pose() ? 0 : content.version(ShownLayer::Pose);
        m_uploaded.colors = content.colors() ? 0 : content.version(ShownLayer::Colors);
        return;
    }
    if (m_uploaded.geometry != content.version(ShownLayer::Geometry)) {
        const Scene& scene = *content.scene();
        for (std::size_t i = 0; i < scene.objects.size(); ++i)
            m_renderer->gpuScene().setModelMatrix(i, scene.objects[i].modelMatrix);
        m_uploaded.geometry = content.version(ShownLayer::Geometry);
    }
}

// Object 0 as the pose layer shows it: evaluated on the GPU where its source allows,
// else the CPU's positions; without a pose, the scene's own positions again.
void ViewportRenderer::syncPose()
{
    const std::uint64_t version = m_content->version(ShownLayer::Pose);
    if (m_uploaded.pose == version)
        return;
    if (const ShownPose* pose = m_content->pose()) {
        if (evaluatePoseOnGpu(*pose)) {
            m_poseEvaluation = m_gpuPose.evaluator->kind();
        } else {
            m_renderer->gpuScene().updatePositions(0, pose->positions);
            m_poseEvaluation = PoseEvaluation::Uploaded;
        }
        m_uploaded.posed = true;
    } else {
        if (m_uploaded.posed)
            m_renderer->gpuScene().updatePositions(0, m_content->scene()->objects.front().mesh.positions);
        m_uploaded.posed = false;
        m_poseEvaluation = PoseEvaluation::Uploaded;
    }
    m_uploaded.pose = version;
}

// The one GPU path of skinned poses and subdivision surfaces: the evaluator of the pose's
// source, made in this context on first use; false when it cannot run (the CPU's positions
// are uploaded instead, and that source is not tried again until another one was shown).
// A GPU reset is the frame policy's to handle.
bool ViewportRenderer::evaluatePoseOnGpu(const ShownPose& pose)
{
    std::shared_ptr<const void> source = gpuPoseSource(pose);
    if (!source)
        return false;
    if (source != m_gpuPose.source)
        m_gpuPose = GpuPose{std::move(source), nullptr, false};
    if (m_gpuPose.failed)
        return false;
    try {
        if (!m_gpuPose.evaluator)
            m_gpuPose.evaluator = makeGpuPoseEvaluator(m_renderer->gl(), pose);
        m_gpuPose.evaluator->evaluate(m_renderer->gpuScene(), 0, pose);
        return true;
    } catch (const GlContextLostError&) {
        throw;
    } catch (const std::exception&) {
        m_gpuPose.evaluator.reset();
        m_gpuPose.failed = true;
        return false;
    }
}

void ViewportRenderer::syncColors()
{
    const std::uint64_t version = m_content->version(ShownLayer::Colors);
    if (m_uploaded.colors == version)
        return;
    const std::vector<std::uint32_t>* colors = m_content->colors();
    m_renderer->gpuScene().setVertexColors(colors ? *colors : std::vector<std::uint32_t>{});
    m_uploaded.colors = version;
}

// Another chain (or a new dynamic renderer) uploads every level; the same chain only its
// replaced shown level and the levels appended since, so the earlier sets'
// characterizations stay cached (a drag, playback going forward).
void ViewportRenderer::syncChain()
{
    const ShownChain& chain = *m_content->chain();
    std::vector<std::shared_ptr<const DynamicChainLevel>>& held = m_uploaded.levels;
    const bool extends = m_uploaded.chainId == chain.id && !held.empty() && held.size() <= chain.levels.size() &&
                         std::equal(held.begin(), held.end() - 1, chain.levels.begin());
    if (!extends) {
        m_dynamic->setChain(*chain.chain);
        held.clear();
        for (const DynamicChainLevel& level : chain.chain->levels)
            held.emplace_back(chain.chain, &level);
        m_uploaded.chainId = chain.id;
    }
    const std::size_t last = held.size() - 1;
    if (held[last] != chain.levels[last]) {
        m_dynamic->setShownLevel(*chain.levels[last]);
        held[last] = chain.levels[last];
    }
    for (std::size_t i = held.size(); i < chain.levels.size(); ++i) {
        m_dynamic->appendLevel(*chain.levels[i]);
        held.push_back(chain.levels[i]);
    }
}

// The designed mesh is the scene's only object, so the scene's colours are per mesh vertex.
void ViewportRenderer::syncDynamicColors()
{
    const std::uint64_t version = m_content->version(ShownLayer::Colors);
    if (m_uploaded.dynamicColors == version)
        return;
    const std::vector<std::uint32_t>* colors = m_content->colors();
    m_dynamic->setShownVertexColors(colors ? *colors : std::vector<std::uint32_t>{});
    m_uploaded.dynamicColors = version;
}

// The static path shows the pose and colours in the scene's buffers; the dynamic path
// renders the chain's levels, which carry their own positions and the shown colours.
void ViewportRenderer::renderFrame(const Camera& camera, QSize size, GLuint framebuffer)
{
    if (!m_content->scene())
        throw std::invalid_argument("There is no scene to render.");
    syncGeometry();
    applyMethod();
    if (dynamicFrames()) {
        renderDynamicFrame(camera, size);
    } else {
        if (!m_content->chain())
            m_uploaded.levels.clear(); // no chain shown: keep none alive for the GPU's copy
        syncPose();
        syncColors();
        m_renderer->render(camera, m_settings, size.width(), size.height());
        m_dynamicStats.reset();
    }
    m_renderer->blitTo(framebuffer);
    recordFrame(camera, size);
}

void ViewportRenderer::renderDynamicFrame(const Camera& camera, QSize size)
{
    if (!m_dynamic) {
        m_dynamic = std::make_unique<DynamicTrimRenderer>(*m_renderer);
        m_uploaded.chainId = 0;
        m_uploaded.levels.clear();
        m_uploaded.dynamicColors = 0;
    }
    syncChain();
    syncDynamicColors();
    m_dynamic->render(camera, m_settings, size.width(), size.height());
    m_dynamicStats = m_dynamic->lastStats();
}

void ViewportRenderer::recordFrame(const Camera& camera, QSize size)
{
    FrameStats issued;
    issued.serial = m_renderer->lastIssuedFrame();
    m_issued.push_back(ViewFrame{camera, m_settings, m_parameters.k, m_parameters, size, issued, std::nullopt,
                                 m_content->scene(), m_dynamicStats});
    (void)adoptArrivedFrame();
}

const std::optional<DynamicFrameStats>& ViewportRenderer::lastDynamicStats() const
{
    static const std::optional<DynamicFrameStats> none;
    return m_lastFrame ? m_lastFrame->dynamicStats : none;
}

void ViewportRenderer::forgetLastFrame()
{
    m_lastFrame.reset();
    m_issued.clear();
}

bool ViewportRenderer::collectFrames()
{
    if (!m_renderer || m_issued.empty())
        return false;
    (void)m_renderer->collectFrames();
    return adoptArrivedFrame();
}

void ViewportRenderer::finishFrames()
{
    if (!m_renderer || m_issued.empty())
        return;
    m_renderer->finishFrames();
    (void)adoptArrivedFrame();
}

// A frame that lost fragments gets the largest per-pixel count of the method's storage,
// read back (a wait) only while it is the frame the storage holds.
bool ViewportRenderer::adoptArrivedFrame()
{
    const FrameStats& stats = m_renderer->lastStats();
    DynamicFrameStats superseded;
    while (!m_issued.empty() && m_issued.front().stats.serial < stats.serial) {
        if (const std::optional<DynamicFrameStats>& dynamic = m_issued.front().dynamicStats) {
            superseded.characterizedLevels += dynamic->characterizedLevels;
            superseded.characterizeMilliseconds += dynamic->characterizeMilliseconds;
        }
        m_issued.pop_front(); // superseded by a newer result
    }
    if (m_issued.empty() || m_issued.front().stats.serial != stats.serial)
        return false;
    ViewFrame frame = std::move(m_issued.front());
    m_issued.pop_front();
    if (frame.dynamicStats) {
        frame.dynamicStats->characterizedLevels += superseded.characterizedLevels;
        frame.dynamicStats->characterizeMilliseconds += superseded.characterizeMilliseconds;
    }
    frame.stats = stats;
    const FrameCounts& counts = stats.counts;
    const bool lost = counts.overflowPixels > 0 || counts.unresolvedPixels > 0 || counts.fragmentsLost > 0;
    if (lost && m_issued.empty() && stats.serial == m_renderer->lastIssuedFrame()) {
        const std::optional<PixelOccupancy> occupancy = m_renderer->readOccupancy();
        if (occupancy && !occupancy->held.empty())
            frame.largestPixelCount = *std::max_element(occupancy->held.begin(), occupancy->held.end());
    }
    m_lastFrame = std::move(frame);
    return true;
}

MethodMeasurement ViewportRenderer::measure(FragmentMethodKind method, int frames, const Camera& camera, QSize size)
{
    MethodMeasurement result;
    finishFrames();
    m_renderer->setPipelined(false); // each measured frame waits for its own time
    try {
        if (!m_content->scene())
            throw std::invalid_argument("There is no scene to render.");
        syncGeometry();
        syncPose();
        syncColors();
        m_renderer->setMethod(method);
        m_renderer->setParameters(m_parameters);
        m_renderer->render(camera, m_settings, size.width(), size.height()); // warm-up: shaders, storage
        for (int i = 0; i < frames; ++i) {
            m_renderer->render(camera, m_settings, size.width(), size.height());
            result.times.add(m_renderer->lastStats());
        }
        result.lastStats = m_renderer->lastStats();
    } catch (...) {
        m_renderer->setMethod(m_policy.effectiveMethod());
        m_renderer->setPipelined(true);
        throw;
    }
    m_renderer->setMethod(m_policy.effectiveMethod());
    m_renderer->setPipelined(true);
    return result;
}

} // namespace trimlab::render
