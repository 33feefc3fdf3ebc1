#include "render/dynamic_trim_renderer.h"

#include "render/gl/gl_error.h"
#include "render/frame/gpu_scene.h"
#include "render/gl/bindings.h"

#include <QElapsedTimer>

#include <stdexcept>

namespace trimlab::render {

namespace {

// shaders/common/dynamic_state.glsl: a two-word header, then ivec2 per pixel; a bit
// vector is 8 words plus a flag word per pixel.
constexpr std::size_t kStateHeaderBytes = 2 * sizeof(GLuint);
constexpr std::size_t kBitsWordsPerPixel = 9;

void allocate(GlFunctions& gl, GlBuffer& buffer, std::size_t bytes, const char* what)
{
    buffer = GlBuffer(gl);
    gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer.id());
    gl.glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(bytes), nullptr, GL_DYNAMIC_COPY);
    checkAllocation(gl, what, double(bytes));
}

void clearWords(GlFunctions& gl, const GlBuffer& buffer, std::size_t offset, std::size_t bytes)
{
    const GLuint zero = 0;
    gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer.id());
    gl.glClearBufferSubData(GL_SHADER_STORAGE_BUFFER, GL_R32UI, GLintptr(offset), GLsizeiptr(bytes), GL_RED_INTEGER,
                            GL_UNSIGNED_INT, &zero);
}

} // namespace

DynamicTrimRenderer::DynamicTrimRenderer(TrimRenderer& renderer) : m_renderer(renderer), m_gl(renderer.gl())
{
}

DynamicTrimRenderer::~DynamicTrimRenderer() = default;

void DynamicTrimRenderer::setChain(const DynamicChain& chain)
{
    if (chain.levels.empty())
        throw std::invalid_argument("a dynamic chain needs at least one level.");
    std::vector<std::unique_ptr<GpuScene>> levels;
    for (const DynamicChainLevel& level : chain.levels) {
        levels.push_back(std::make_unique<GpuScene>(m_gl));
        levels.back()->upload(level.frame.scene);
    }
    m_levels = std::move(levels);
    m_rules.clear();
    for (const DynamicChainLevel& level : chain.levels)
        m_rules.push_back(level.rule);
    m_baseRule = chain.baseRule;
    m_meshVertices = chain.levels.back().frame.scene.objects.front().mesh.positions.size();
    m_characterized = 0;
    if (m_shownColors.size() != m_meshVertices)
        m_shownColors.clear();
    applyShownColors();
}

void DynamicTrimRenderer::setShownLevel(const DynamicChainLevel& level)
{
    if (m_levels.empty())
        throw std::invalid_argument("set a dynamic chain before replacing its shown level.");
    m_levels.back()->upload(level.frame.scene);
    m_rules.back() = level.rule;
    applyShownColors();
}

void DynamicTrimRenderer::appendLevel(const DynamicChainLevel& level)
{
    if (m_levels.empty())
        throw std::invalid_argument("set a dynamic chain before appending a level to it.");
    auto scene = std::make_unique<GpuScene>(m_gl);
    scene->upload(level.frame.scene);
    m_levels.back()->setVertexColors({}); // a characterization level draws no colors
    m_levels.push_back(std::move(scene));
    m_rules.push_back(level.rule);
    applyShownColors();
}

void DynamicTrimRenderer::setShownVertexColors(std::vector<std::uint32_t> rgba8)
{
    if (!rgba8.empty() && rgba8.size() != m_meshVertices)
        throw std::invalid_argument("setShownVertexColors: the designed mesh has " + std::to_string(m_meshVertices) +
                                    " vertices, got " + std::to_string(rgba8.size()) + " colors.");
    m_shownColors = std::move(rgba8);
    applyShownColors();
}

// The shown level holds the mesh's vertex array once per frame-class object
// (dynamic_frame_scene.h), so the colors are repeated for each.
void DynamicTrimRenderer::applyShownColors()
{
    if (m_levels.empty())
        return;
    std::vector<std::uint32_t> perObject;
    if (!m_shownColors.empty()) {
        perObject.reserve(3 * m_shownColors.size());
        for (int object = 0; object < 3; ++object)
            perObject.insert(perObject.end(), m_shownColors.begin(), m_shownColors.end());
    }
    m_levels.back()->setVertexColors(perObject);
}

void DynamicTrimRenderer::resizeState(int width, int height)
{
    if (width == m_stateWidth && height == m_stateHeight)
        return;
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    m_stateWidth = 0;
    m_stateHeight = 0;
    m_bytes = 0;
    allocate(m_gl, m_state, kStateHeaderBytes + pixels * 2 * sizeof(GLint), "dynamic-rule pixel state");
    for (GlBuffer& bits : m_bits)
        allocate(m_gl, bits, pixels * kBitsWordsPerPixel * sizeof(GLuint), "characterization bit vectors");
    m_stateWidth = width;
    m_stateHeight = height;
    m_bytes = kStateHeaderBytes + pixels * (2 * sizeof(GLint) + 2 * kBitsWordsPerPixel * sizeof(GLuint));
    m_characterized = 0;
}

// Zeroes the per-pixel counts of Algorithm 8.12 before a level's geometry pass.
void DynamicTrimRenderer::clearState(int width, int height)
{
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    const GLuint header[2] = {GLuint(width), 0u};
    m_gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, m_state.id());
    m_gl.glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(header), header);
    clearWords(m_gl, m_state, kStateHeaderBytes, pixels * 2 * sizeof(GLint));
    m_gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kDynamicStateStorage, m_state.id());
    m_gl.glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

// Levels m_characterized .. n−2, each in characterize mode reading the previous level's
// bit vectors (level 0: the base mesh's static rule) and writing its own; the two bit
// vectors alternate, so the one the last cached level wrote is read first.
void DynamicTrimRenderer::characterizeLevels(const Camera& camera, const TrimSettings& settings, int width, int height)
{
    TrimSettings whole = settings;
    whole.setClipSet(ClipSet{}); // a characterization covers the whole ray
    whole.trimEnabled = true;
    int written = m_characterized == 0 ? 0 : 1 - m_shownReference;
    for (std::size_t level = m_characterized; level + 1 < m_levels.size(); ++level) {
        const int read = 1 - written;
        clearState(width, height);
        clearWords(m_gl, m_bits[written], 0,
                   std::size_t(width) * std::size_t(height) * kBitsWordsPerPixel * sizeof(GLuint));
        m_gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kReferenceBitsStorage, m_bits[read].id());
        m_gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kCharacterizationBitsStorage, m_bits[written].id());
        m_gl.glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
        const TrimMode mode{true, true, int(m_rules[level]), level == 0};
        m_renderer.render(*m_levels[level], mode, camera, whole, width, height);
        m_gl.glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        ++m_stats.characterizedLevels;
        m_shownReference = written;
        written = read;
    }
    m_characterized = m_levels.size() - 1;
}

bool DynamicTrimRenderer::viewChanged(const Camera& camera, const TrimSettings& settings) const
{
    return !(camera == m_cachedCamera) || settings.rule != m_cachedBaseRule ||
           int(m_renderer.method()) != m_cachedMethod || m_renderer.k() != m_cachedK;
}

void DynamicTrimRenderer::render(const Camera& camera, const TrimSettings& settings, int width, int height)
{
    if (m_levels.empty())
        throw std::invalid_argument("no dynamic chain to render.");
    m_stats = DynamicFrameStats{};
    m_stats.levels = int(m_levels.size());
    resizeState(width, height);
    if (viewChanged(camera, settings))
        m_characterized = 0;
    if (m_characterized + 1 < m_levels.size()) {
        QElapsedTimer timer;
        timer.start();
        characterizeLevels(camera, settings, width, height);
        m_stats.characterizeMilliseconds = double(timer.nsecsElapsed()) * 1e-6;
        m_cachedCamera = camera;
        m_cachedBaseRule = settings.rule;
        m_cachedMethod = int(m_renderer.method());
        m_cachedK = m_renderer.k();
    }
    QElapsedTimer timer;
    timer.start();
    clearState(width, height);
    m_gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kReferenceBitsStorage, m_bits[m_shownReference].id());
    // Nothing is written in display mode, but the binding must name a buffer.
    m_gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kCharacterizationBitsStorage,
                          m_bits[1 - m_shownReference].id());
    const TrimMode mode{true, false, int(m_rules.back()), m_levels.size() == 1};
    m_renderer.render(*m_levels.back(), mode, camera, settings, width, height);
    m_stats.frameMilliseconds = double(timer.nsecsElapsed()) * 1e-6;
}

} // namespace trimlab::render
