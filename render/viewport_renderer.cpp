#include "render/viewport_renderer.h"

#include "render/frame/gpu_scene.h"
#include "render/frame/gpu_skinning.h"
#include "render/frame/gpu_subdivision.h"
#include "render/gl/context_reset.h"
#include "render/gl/gl_error.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace trimlab::render {

ViewportRenderer::ViewportRenderer() = default;

ViewportRenderer::~ViewportRenderer() = default;

void ViewportRenderer::setScene(std::shared_ptr<const Scene> scene)
{
    m_scene = std::move(scene);
    m_posedScene.reset();
    m_sceneUploaded = false;
    m_lastFrame.reset();
    m_pose.clear();
    m_skinning.reset();
    m_subdivision.reset();
    m_vertexColors.clear();
    m_chain.reset(); // a chain belongs to the previous scene's mesh
    m_level.reset();
    m_appended.clear();
    m_chainLastLevel.reset();
    m_policy.reset();
}

void ViewportRenderer::setSceneTransforms(std::shared_ptr<const Scene> scene)
{
    if (!m_scene || !scene || scene->objects.size() != m_scene->objects.size())
        throw std::invalid_argument("setSceneTransforms: the new scene does not have the shown scene's objects.");
    for (std::size_t i = 0; i < scene->objects.size(); ++i) {
        if (scene->objects[i].mesh.vertexCount() != m_scene->objects[i].mesh.vertexCount() ||
            scene->objects[i].mesh.triangleCount() != m_scene->objects[i].mesh.triangleCount())
            throw std::invalid_argument("setSceneTransforms: object " + std::to_string(i) +
                                        " has another mesh than the one shown.");
    }
    m_scene = std::move(scene);
    m_posedScene.reset();
    m_transformsDirty = true;
}

void ViewportRenderer::showPose(const std::vector<glm::vec3>& positions)
{
    const std::size_t expected = m_scene && !m_scene->objects.empty() ? m_scene->objects.front().mesh.vertexCount() : 0;
    if (positions.size() != expected || expected == 0)
        throw std::invalid_argument("showPose: the scene's first object has " + std::to_string(expected) +
                                    " vertices, the pose " + std::to_string(positions.size()) + ".");
    m_pose = positions;
    m_poseDirty = true;
    m_posedScene.reset();
    m_skinning.reset();
    m_subdivision.reset();
}

void ViewportRenderer::showSkinnedPose(std::shared_ptr<const SkinningModel> model, std::size_t pose,
                                       const std::vector<glm::vec3>& positions)
{
    if (!model || pose >= model->poseCount())
        throw std::invalid_argument("showSkinnedPose: pose " + std::to_string(pose) + " of a model with " +
                                    std::to_string(model ? model->poseCount() : 0) + " poses.");
    showPose(positions);
    if (model != m_gpuSkinningModel)
        m_gpuSkinningFailed = false;
    m_skinning = std::move(model);
    m_skinnedPose = pose;
}

void ViewportRenderer::showSubdivisionPose(std::shared_ptr<const SubdivisionStencils> stencils,
                                           std::vector<glm::dvec3> controlPoints,
                                           const std::vector<glm::vec3>& positions)
{
    if (!stencils || controlPoints.size() != stencils->cageVertexCount)
        throw std::invalid_argument("showSubdivisionPose: " + std::to_string(controlPoints.size()) +
                                    " control points for a cage of " +
                                    std::to_string(stencils ? stencils->cageVertexCount : 0) + ".");
    showPose(positions);
    if (stencils != m_gpuSubdivisionStencils)
        m_gpuSubdivisionFailed = false;
    m_subdivision = std::move(stencils);
    m_controlPoints = std::move(controlPoints);
}

void ViewportRenderer::setVertexColors(std::vector<std::uint32_t> rgba8)
{
    std::size_t vertices = 0;
    if (m_scene)
        for (const SceneObject& object : m_scene->objects)
            vertices += object.mesh.vertexCount();
    if (!rgba8.empty() && rgba8.size() != vertices)
        throw std::invalid_argument("setVertexColors: the scene has " + std::to_string(vertices) + " vertices, got " +
                                    std::to_string(rgba8.size()) + " colors.");
    m_vertexColors = std::move(rgba8);
    m_colorsDirty = true;
    m_dynamicColorsDirty = true;
}

std::shared_ptr<const Scene> ViewportRenderer::posedScene()
{
    if (!m_posedScene && m_scene) {
        if (m_pose.empty()) {
            m_posedScene = m_scene;
        } else {
            auto posed = std::make_shared<Scene>(*m_scene);
            posed->objects.front().mesh.positions = m_pose;
            m_posedScene = std::move(posed);
        }
    }
    return m_posedScene;
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

void ViewportRenderer::setDynamicChain(std::shared_ptr<const DynamicChain> chain)
{
    m_chain = std::move(chain);
    m_policy.clearStop();
    m_level.reset();
    m_appended.clear();
    m_appendedUploaded = 0;
    m_chainLastLevel.reset();
    m_chainDirty = m_chain != nullptr;
    m_levelDirty = false;
}

// A replaced shown level is folded into the history before the new level follows it; if
// the replacement never reached the GPU, the whole chain goes up again (a drag followed
// at once by an append: rare, and correct rather than clever).
void ViewportRenderer::appendDynamicLevel(std::shared_ptr<const DynamicChainLevel> level)
{
    if (!m_chain || !level)
        return;
    if (m_level) {
        if (m_appended.empty())
            m_chainLastLevel = m_level;
        else
            m_appended.back() = m_level;
        if (m_levelDirty)
            m_chainDirty = true;
        m_level.reset();
        m_levelDirty = false;
    }
    m_appended.push_back(std::move(level));
}

std::size_t ViewportRenderer::dynamicLevelCount() const
{
    return m_chain ? m_chain->levels.size() + m_appended.size() : 0;
}

void ViewportRenderer::setDynamicShownLevel(std::shared_ptr<const DynamicChainLevel> level)
{
    if (!m_chain)
        return;
    m_level = std::move(level);
    m_levelDirty = m_level != nullptr;
}

const DynamicChainLevel* ViewportRenderer::dynamicShownLevel() const
{
    if (m_level)
        return m_level.get();
    if (!m_appended.empty())
        return m_appended.back().get();
    if (m_chainLastLevel)
        return m_chainLastLevel.get();
    return m_chain && !m_chain->levels.empty() ? &m_chain->levels.back() : nullptr;
}

void ViewportRenderer::initialize(QOpenGLContext& context)
{
    m_sceneUploaded = false;
    m_renderer = std::make_unique<TrimRenderer>(context);
    applyMethod();
}

void ViewportRenderer::release()
{
    m_dynamic.reset(); // its GL objects go first: it holds a reference to the renderer
    m_gpuSkinning.reset();
    m_gpuSubdivision.reset();
    m_renderer.reset();
    m_sceneUploaded = false;
    m_chainDirty = m_chain != nullptr;
    m_levelDirty = m_level != nullptr;
}

void ViewportRenderer::applyMethod()
{
    m_renderer->setMethod(m_policy.effectiveMethod());
    m_renderer->setParameters(m_parameters);
}

FrameDemands ViewportRenderer::frameDemands() const
{
    return {m_chain && m_settings.trimEnabled, needsInspectionMethod(m_settings)};
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
            m_lastFrame.reset();
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
    m_lastFrame.reset();
    return m_policy.contextLost(reason, frameDemands());
}

// Brings the renderer's scene buffers up to date: the scene itself after setScene() or a
// new context, then the pose and colors when they changed or the scene was re-uploaded.
void ViewportRenderer::syncGpuScene()
{
    if (!m_sceneUploaded) {
        m_renderer->setScene(*m_scene);
        m_sceneUploaded = true;
        m_transformsDirty = false; // the upload carried the current matrices
        m_poseDirty = !m_pose.empty();
        m_colorsDirty = !m_vertexColors.empty();
    }
    if (m_transformsDirty) {
        for (std::size_t i = 0; i < m_scene->objects.size(); ++i)
            m_renderer->gpuScene().setModelMatrix(i, m_scene->objects[i].modelMatrix);
        m_transformsDirty = false;
    }
    if (m_poseDirty) {
        uploadPose();
        m_poseDirty = false;
    }
    if (m_colorsDirty) {
        m_renderer->gpuScene().setVertexColors(m_vertexColors);
        m_colorsDirty = false;
    }
}

void ViewportRenderer::uploadPose()
{
    m_poseOnGpu = (m_skinning && !m_gpuSkinningFailed && skinPoseOnGpu()) ||
                  (m_subdivision && !m_gpuSubdivisionFailed && subdividePoseOnGpu());
    if (!m_poseOnGpu)
        m_renderer->gpuScene().updatePositions(0, m_pose);
}

// The GPU skinning of the shown model, made in this context on first use; false when it
// cannot run (the CPU's pose is uploaded instead, and the model is not tried again). A GPU
// reset is the frame policy's to handle.
bool ViewportRenderer::skinPoseOnGpu()
{
    try {
        if (!m_gpuSkinning || m_gpuSkinningModel != m_skinning) {
            m_gpuSkinning.reset();
            m_gpuSkinningModel = m_skinning;
            m_gpuSkinning = std::make_unique<GpuSkinning>(m_renderer->gl(), *m_skinning);
        }
        m_gpuSkinning->skinPose(m_renderer->gpuScene(), 0, m_skinnedPose);
        return true;
    } catch (const GlContextLostError&) {
        throw;
    } catch (const std::exception&) {
        m_gpuSkinning.reset();
        m_gpuSkinningFailed = true;
        return false;
    }
}

// The same for the shown subdivision surface: its GPU evaluation, made in this context on
// first use; false (the CPU's positions are uploaded, these stencils not tried again) when
// it cannot run.
bool ViewportRenderer::subdividePoseOnGpu()
{
    try {
        if (!m_gpuSubdivision || m_gpuSubdivisionStencils != m_subdivision) {
            m_gpuSubdivision.reset();
            m_gpuSubdivisionStencils = m_subdivision;
            m_gpuSubdivision = std::make_unique<GpuSubdivision>(m_renderer->gl(), *m_subdivision);
        }
        m_gpuSubdivision->evaluate(m_renderer->gpuScene(), 0, m_controlPoints);
        return true;
    } catch (const GlContextLostError&) {
        throw;
    } catch (const std::exception&) {
        m_gpuSubdivision.reset();
        m_gpuSubdivisionFailed = true;
        return false;
    }
}

void ViewportRenderer::renderFrame(const Camera& camera, QSize size, GLuint framebuffer)
{
    syncGpuScene();
    applyMethod();
    if (m_chain && m_settings.trimEnabled) {
        renderDynamicFrame(camera, size);
    } else {
        m_renderer->render(camera, m_settings, size.width(), size.height());
        m_dynamicStats.reset();
    }
    m_renderer->blitTo(framebuffer);
    recordFrame(camera, size);
}

// The chain's levels are uploaded only when the chain changed; a drag replaces only the
// shown level, so the earlier sets' characterizations stay cached.
void ViewportRenderer::renderDynamicFrame(const Camera& camera, QSize size)
{
    if (!m_dynamic) {
        m_dynamic = std::make_unique<DynamicTrimRenderer>(*m_renderer);
        m_dynamicColorsDirty = true;
    }
    if (m_chainDirty) {
        m_dynamic->setChain(*m_chain);
        if (m_chainLastLevel)
            m_dynamic->setShownLevel(*m_chainLastLevel);
        m_appendedUploaded = 0;
        m_chainDirty = false;
        m_levelDirty = m_level != nullptr;
    }
    for (; m_appendedUploaded < m_appended.size(); ++m_appendedUploaded)
        m_dynamic->appendLevel(*m_appended[m_appendedUploaded]);
    if (m_levelDirty) {
        m_dynamic->setShownLevel(*m_level);
        m_levelDirty = false;
    }
    if (m_dynamicColorsDirty) {
        // The designed mesh is the scene's only object, so the scene's colors are per mesh vertex.
        m_dynamic->setShownVertexColors(m_vertexColors);
        m_dynamicColorsDirty = false;
    }
    m_dynamic->render(camera, m_settings, size.width(), size.height());
    m_dynamicStats = m_dynamic->lastStats();
}

void ViewportRenderer::recordFrame(const Camera& camera, QSize size)
{
    const FrameStats& stats = m_renderer->lastStats();
    ViewFrame frame{camera, m_settings, m_parameters.k, m_parameters, size, stats, std::nullopt, m_scene};
    const FrameCounts& counts = stats.counts;
    if (counts.overflowPixels > 0 || counts.unresolvedPixels > 0 || counts.fragmentsLost > 0) {
        const std::optional<PixelOccupancy> occupancy = m_renderer->readOccupancy();
        if (occupancy && !occupancy->held.empty())
            frame.largestPixelCount = *std::max_element(occupancy->held.begin(), occupancy->held.end());
    }
    m_lastFrame = std::move(frame);
}

MethodMeasurement ViewportRenderer::measure(FragmentMethodKind method, int frames, const Camera& camera, QSize size)
{
    MethodMeasurement result;
    try {
        syncGpuScene();
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
        throw;
    }
    m_renderer->setMethod(m_policy.effectiveMethod());
    return result;
}

} // namespace trimlab::render
