#include "render/frame/gpu_subdivision.h"

#include "render/gl/gl_error.h"

#include <opensubdiv/far/stencilTable.h>
#include <opensubdiv/osd/bufferDescriptor.h>
#include <opensubdiv/osd/glComputeEvaluator.h>

#include <dlfcn.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace trimlab::render {

namespace {

namespace Far = OpenSubdiv::Far;
namespace Osd = OpenSubdiv::Osd;

// Far::StencilTable's constructor from compressed rows is protected (Far's factories use
// it); this table is the CPU's rows handed over as they are.
class RowStencilTable : public Far::StencilTable {
public:
    explicit RowStencilTable(const SubdivisionStencils& s)
        : Far::StencilTable(int(s.cageVertexCount), s.offsets, s.sizes, s.indices, s.weights, false, 0)
    {
    }
};

// What libosdGPU's loader does on its first evaluator (dlopen libGL.so.1, ask
// glXGetProcAddressARB), done first here: where it would fail, OpenSubdiv calls a null
// function pointer instead of reporting it.
void requireOpenSubdivGlLoader()
{
    void* library = dlopen("libGL.so.1", RTLD_LAZY | RTLD_LOCAL);
    if (!library)
        throw GlUnavailableError("GPU subdivision: OpenSubdiv loads OpenGL from libGL.so.1, which is not installed (" +
                                 std::string(dlerror()) + "); install libgl1.");
    using GetProcAddress = void* (*)(const unsigned char*);
    const auto getProcAddress = reinterpret_cast<GetProcAddress>(dlsym(library, "glXGetProcAddressARB"));
    const bool found =
        getProcAddress && getProcAddress(reinterpret_cast<const unsigned char*>("glDispatchCompute")) != nullptr;
    // The library stays loaded: OpenSubdiv's loader opens it again and keeps it.
    if (!found)
        throw GlUnavailableError("GPU subdivision: libGL.so.1 gives OpenSubdiv no glXGetProcAddressARB or no "
                                 "glDispatchCompute.");
}

void validateStencils(const SubdivisionStencils& s)
{
    const std::size_t outputs = s.sizes.size();
    if (s.offsets.size() != outputs || s.indices.size() != s.weights.size())
        throw std::invalid_argument("GPU subdivision: the stencil rows are inconsistent.");
    for (std::size_t v = 0; v < outputs; ++v)
        if (s.sizes[v] < 0 || s.offsets[v] < 0 ||
            std::size_t(s.offsets[v]) + std::size_t(s.sizes[v]) > s.indices.size())
            throw std::invalid_argument("GPU subdivision: the stencil of output vertex " + std::to_string(v) +
                                        " lies outside the entries.");
    for (const int c : s.indices)
        if (c < 0 || std::size_t(c) >= s.cageVertexCount)
            throw std::invalid_argument("GPU subdivision: a stencil names cage vertex " + std::to_string(c) + " of " +
                                        std::to_string(s.cageVertexCount) + ".");
}

std::size_t stencilBytes(const SubdivisionStencils& s)
{
    return (s.sizes.size() + s.offsets.size() + s.indices.size()) * sizeof(int) + s.weights.size() * sizeof(float);
}

} // namespace

struct GpuSubdivision::OpenSubdivObjects {
    // The evaluator first: making it loads OpenSubdiv's GL functions, which the table uses.
    std::unique_ptr<Osd::GLComputeEvaluator> evaluator;
    std::unique_ptr<Osd::GLStencilTableSSBO> table;
};

GpuSubdivision::GpuSubdivision(GlFunctions& gl, const SubdivisionStencils& stencils)
    : m_gl(gl),
      m_cageVertexCount(stencils.cageVertexCount),
      m_vertexCount(stencils.outputVertexCount()),
      m_triangleCount(stencils.triangles.size()),
      m_shaders(std::make_unique<ShaderLibrary>(gl)),
      m_osd(std::make_unique<OpenSubdivObjects>()),
      m_controlPoints(gl),
      m_normals(gl, stencils.triangles, stencils.outputVertexCount())
{
    validateStencils(stencils);
    requireOpenSubdivGlLoader();
    const Osd::BufferDescriptor xyz(0, 3, 3);
    m_osd->evaluator.reset(Osd::GLComputeEvaluator::Create(xyz, xyz, Osd::BufferDescriptor(), Osd::BufferDescriptor()));
    if (!m_osd->evaluator)
        throw ShaderBuildError("GPU subdivision: OpenSubdiv's GLSL stencil kernel did not build (its log is on "
                               "standard error).");
    const RowStencilTable table(stencils);
    m_osd->table = std::make_unique<Osd::GLStencilTableSSBO>(&table);
    m_stencilBytes = stencilBytes(stencils);
    checkAllocation(m_gl, "subdivision stencils", double(m_stencilBytes));
    m_packed.resize(3 * m_cageVertexCount);
    // Build the normals' program now: a shader error belongs to the construction.
    m_shaders->program(QStringLiteral("vertex_normals"));
}

GpuSubdivision::~GpuSubdivision() = default;

std::size_t GpuSubdivision::memoryBytes() const
{
    return m_stencilBytes + m_packed.size() * sizeof(float) + m_normals.memoryBytes();
}

void GpuSubdivision::requireObject(const GpuObjectGeometry& object, std::size_t objectIndex) const
{
    if (object.vertexCount != m_vertexCount || object.triangleCount != m_triangleCount)
        throw std::invalid_argument("GPU subdivision: object " + std::to_string(objectIndex) + " has " +
                                    std::to_string(object.vertexCount) + " vertices and " +
                                    std::to_string(object.triangleCount) + " triangles, the surface " +
                                    std::to_string(m_vertexCount) + " and " + std::to_string(m_triangleCount) + ".");
}

void GpuSubdivision::uploadControlPoints(std::span<const glm::dvec3> controlPoints)
{
    if (controlPoints.size() != m_cageVertexCount)
        throw std::invalid_argument("GPU subdivision: " + std::to_string(controlPoints.size()) +
                                    " control points for a cage of " + std::to_string(m_cageVertexCount) + ".");
    for (std::size_t c = 0; c < controlPoints.size(); ++c) {
        const glm::dvec3& p = controlPoints[c];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw std::invalid_argument("GPU subdivision: control point " + std::to_string(c) + " is not finite.");
        m_packed[3 * c] = float(p.x);
        m_packed[3 * c + 1] = float(p.y);
        m_packed[3 * c + 2] = float(p.z);
    }
    // A new store each time (orphaning): the previous evaluation may still read the old one.
    const auto bytes = GLsizeiptr(std::max<std::size_t>(1, m_packed.size()) * sizeof(float));
    m_gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, m_controlPoints.id());
    m_gl.glBufferData(GL_SHADER_STORAGE_BUFFER, bytes, m_packed.empty() ? nullptr : m_packed.data(), GL_STREAM_DRAW);
    checkAllocation(m_gl, "subdivision control points", double(bytes));
}

void GpuSubdivision::evaluate(GpuScene& scene, std::size_t objectIndex, std::span<const glm::dvec3> controlPoints)
{
    const GpuObjectGeometry object = scene.objectGeometry(objectIndex);
    requireObject(object, objectIndex);
    uploadControlPoints(controlPoints);
    const Osd::BufferDescriptor source(0, 3, 3);
    const Osd::BufferDescriptor destination(int(3 * object.baseVertex), 3, 3);
    const Osd::GLStencilTableSSBO& table = *m_osd->table;
    // One dispatch covers at most 65535 groups of 64 (GL 4.3's guaranteed group count).
    constexpr std::size_t kBatch = std::size_t(65535) * 64;
    for (std::size_t start = 0; start < m_vertexCount; start += kBatch) {
        const std::size_t end = std::min(m_vertexCount, start + kBatch);
        if (!m_osd->evaluator->EvalStencils(m_controlPoints.id(), source, object.positions, destination, 0,
                                            Osd::BufferDescriptor(), 0, Osd::BufferDescriptor(), table.GetSizesBuffer(),
                                            table.GetOffsetsBuffer(), table.GetIndicesBuffer(),
                                            table.GetWeightsBuffer(), 0, 0, int(start), int(end)))
            throw GlError("GPU subdivision: OpenSubdiv's stencil kernel is missing.");
    }
    // OpenSubdiv orders only texture fetches after its pass; the normals read the
    // positions as storage.
    m_gl.glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    m_normals.recompute(*m_shaders, object);
    m_gl.glMemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
                         GL_BUFFER_UPDATE_BARRIER_BIT);
}

} // namespace trimlab::render
