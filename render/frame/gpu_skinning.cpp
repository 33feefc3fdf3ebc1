#include "render/frame/gpu_skinning.h"

#include "render/frame/vertex_dispatch.h"
#include "render/gl/bindings.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace trimlab::render {

namespace {

// The modes of shaders/skinning.comp.
constexpr int kModeCopy = 0;
constexpr int kModeLbs = 1;
constexpr int kModeDqs = 2;

constexpr std::size_t kLbsDoubles = 12; // linear part column by column, translation
constexpr std::size_t kDqsDoubles = 8;  // real x y z w, dual x y z w

std::size_t doublesPerBone(SkinningMethod method)
{
    return method == SkinningMethod::Lbs ? kLbsDoubles : kDqsDoubles;
}

std::invalid_argument modelProblem(const std::string& what)
{
    return std::invalid_argument("GPU skinning: " + what);
}

void requireEvaluable(const SkinningModel& model)
{
    if (model.poseCount() == 0)
        throw modelProblem("the model has no poses.");
    if (model.weights.vertices.size() != model.vertexCount())
        throw modelProblem(std::to_string(model.weights.vertices.size()) + " weighted vertices for " +
                           std::to_string(model.vertexCount()) + " rest positions.");
    if (model.restPose >= model.poseCount())
        throw modelProblem("the rest pose " + std::to_string(model.restPose) + " is not one of " +
                           std::to_string(model.poseCount()) + " poses.");
    for (std::size_t v = 0; v < model.weights.vertices.size(); ++v) {
        const VertexInfluences& in = model.weights.vertices[v];
        if (in.count == 0 || in.count > kMaxInfluences)
            throw modelProblem("vertex " + std::to_string(v) + " has " + std::to_string(in.count) + " influences.");
        for (std::uint32_t i = 0; i < in.count; ++i)
            if (in.bones[i] >= model.boneCount())
                throw modelProblem("vertex " + std::to_string(v) + " names bone " + std::to_string(in.bones[i]) +
                                   " of " + std::to_string(model.boneCount()) + ".");
    }
    const bool lbs = model.method == SkinningMethod::Lbs;
    for (std::size_t t = 0; t < model.poseCount(); ++t) {
        const std::size_t bones = lbs ? model.affine[t].size() : model.rigid[t].size();
        if (bones != model.boneCount())
            throw modelProblem("pose " + std::to_string(t) + " has " + std::to_string(bones) + " transforms for " +
                               std::to_string(model.boneCount()) + " bones.");
    }
}

std::size_t largestInfluenceCount(const SkinningWeights& weights)
{
    std::uint32_t largest = 1;
    for (const VertexInfluences& in : weights.vertices)
        largest = std::max(largest, in.count);
    return largest;
}

void appendAffine(std::vector<double>& out, const Affine3& a)
{
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            out.push_back(a.linear[c][r]);
    out.insert(out.end(), {a.translation.x, a.translation.y, a.translation.z});
}

void appendDualQuaternion(std::vector<double>& out, const DualQuaternion& q)
{
    out.insert(out.end(), {q.real.x, q.real.y, q.real.z, q.real.w, q.dual.x, q.dual.y, q.dual.z, q.dual.w});
}

std::vector<double> packTransforms(const SkinningModel& model)
{
    std::vector<double> packed;
    packed.reserve(model.poseCount() * model.boneCount() * doublesPerBone(model.method));
    for (std::size_t t = 0; t < model.poseCount(); ++t) {
        if (model.method == SkinningMethod::Lbs)
            for (const Affine3& a : model.affine[t])
                appendAffine(packed, a);
        else
            for (const DualQuaternion& q : model.rigid[t])
                appendDualQuaternion(packed, q);
    }
    return packed;
}

std::vector<double> packPositions(const std::vector<glm::dvec3>& positions)
{
    std::vector<double> packed;
    packed.reserve(3 * positions.size());
    for (const glm::dvec3& p : positions)
        packed.insert(packed.end(), {p.x, p.y, p.z});
    return packed;
}

// The SkinningInfluences layout of shaders/skinning.comp: per vertex the count, then
// `stride` bones.
std::vector<std::uint32_t> packInfluences(const SkinningWeights& weights, std::size_t stride)
{
    std::vector<std::uint32_t> packed(weights.vertices.size() * (stride + 1), 0u);
    for (std::size_t v = 0; v < weights.vertices.size(); ++v) {
        const VertexInfluences& in = weights.vertices[v];
        packed[v * (stride + 1)] = in.count;
        std::copy_n(in.bones.begin(), in.count, packed.begin() + std::ptrdiff_t(v * (stride + 1) + 1));
    }
    return packed;
}

std::vector<double> packWeights(const SkinningWeights& weights, std::size_t stride)
{
    std::vector<double> packed(weights.vertices.size() * stride, 0.0);
    for (std::size_t v = 0; v < weights.vertices.size(); ++v) {
        const VertexInfluences& in = weights.vertices[v];
        std::copy_n(in.weights.begin(), in.count, packed.begin() + std::ptrdiff_t(v * stride));
    }
    return packed;
}

template <class T>
std::size_t uploadStorage(GlFunctions& gl, const GlBuffer& buffer, const std::vector<T>& data, const char* what)
{
    // Never an empty buffer: binding one is an error.
    const std::size_t bytes = std::max<std::size_t>(sizeof(T), data.size() * sizeof(T));
    gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer.id());
    gl.glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(bytes), data.empty() ? nullptr : data.data(), GL_STATIC_DRAW);
    checkAllocation(gl, what, double(bytes));
    return bytes;
}

// Only the chain and the rest pose of `model`: what SkinningModel::previousPose reads.
SkinningModel chainShape(SkinningChain chain, std::size_t restPose)
{
    SkinningModel shape;
    shape.chain = chain;
    shape.restPose = restPose;
    return shape;
}

} // namespace

GpuSkinning::GpuSkinning(GlFunctions& gl, const SkinningModel& model)
    : m_gl(gl),
      m_shaders(std::make_unique<ShaderLibrary>(gl)),
      m_method(model.method),
      m_chain(model.chain),
      m_restPose(model.restPose),
      m_restPoseMoves(restPoseMoves(model)),
      m_vertexCount(model.vertexCount()),
      m_triangleCount(model.triangles.size()),
      m_boneCount(model.boneCount()),
      m_poseCount(model.poseCount()),
      m_stride(0),
      m_rest(gl),
      m_influences(gl),
      m_weights(gl),
      m_chainState(gl),
      m_transforms(gl),
      m_normals(gl, model.triangles, model.vertexCount())
{
    requireEvaluable(model);
    m_stride = largestInfluenceCount(model.weights);
    m_poseTransforms = packTransforms(model);
    const std::vector<double> rest = packPositions(model.restPositions);
    m_sharedBytes = uploadStorage(m_gl, m_rest, rest, "skinning rest positions") +
                    uploadStorage(m_gl, m_influences, packInfluences(model.weights, m_stride), "skinning influences") +
                    uploadStorage(m_gl, m_weights, packWeights(model.weights, m_stride), "skinning weights");
    if (m_chain == SkinningChain::PoseToPose)
        m_sharedBytes += uploadStorage(m_gl, m_chainState, rest, "skinning chain state");
    // Build the program now: a shader error belongs to the construction, not to a frame.
    m_shaders->program(QStringLiteral("skinning"));
    m_shaders->program(QStringLiteral("vertex_normals"));
}

GpuSkinning::~GpuSkinning() = default;

std::size_t GpuSkinning::memoryBytes() const
{
    return m_sharedBytes + m_transformsBytes + m_normals.memoryBytes();
}

GpuSkinning::ChainWalk GpuSkinning::walkTo(std::size_t pose) const
{
    const SkinningModel shape = chainShape(m_chain, m_restPose);
    std::vector<std::size_t> path; // the rest pose's successors up to `pose`, first step first
    for (std::size_t t = pose; t != m_restPose; t = shape.previousPose(t))
        path.push_back(t);
    std::reverse(path.begin(), path.end());
    if (!m_chainPose)
        return {true, path};
    if (*m_chainPose == m_restPose)
        return {false, path};
    const auto held = std::find(path.begin(), path.end(), *m_chainPose);
    if (held == path.end()) // behind the state or on the other side of the rest pose
        return {true, path};
    return {false, std::vector<std::size_t>(held + 1, path.end())};
}

void GpuSkinning::uploadTransforms(const std::vector<std::size_t>& poses)
{
    const std::size_t perPose = m_boneCount * doublesPerBone(m_method);
    std::vector<double> data;
    data.reserve(std::max<std::size_t>(1, poses.size() * perPose));
    for (std::size_t t : poses)
        data.insert(data.end(), m_poseTransforms.begin() + std::ptrdiff_t(t * perPose),
                    m_poseTransforms.begin() + std::ptrdiff_t((t + 1) * perPose));
    // A new store each time (orphaning): a pass of the previous pose may still read the old one.
    m_transformsBytes = uploadStorage(m_gl, m_transforms, data, "bone transforms");
}

void GpuSkinning::bindCommon(GLuint program, const GpuObjectGeometry& object, GLuint source)
{
    m_gl.glUseProgram(program);
    m_gl.glUniform1ui(m_gl.glGetUniformLocation(program, "u_vertexCount"), GLuint(m_vertexCount));
    m_gl.glUniform1ui(m_gl.glGetUniformLocation(program, "u_sceneBaseVertex"), GLuint(object.baseVertex));
    m_gl.glUniform1ui(m_gl.glGetUniformLocation(program, "u_stride"), GLuint(m_stride));
    m_gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kSkinningSourceStorage, source);
    m_gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kSkinningInfluencesStorage, m_influences.id());
    m_gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kSkinningWeightsStorage, m_weights.id());
    m_gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kScenePositionsStorage, object.positions);
}

void GpuSkinning::runStep(GLuint program, int mode, std::size_t transformSlot, bool keepChain, bool writeScene)
{
    m_gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kSkinningTransformsStorage, m_transforms.id());
    m_gl.glUniform1i(m_gl.glGetUniformLocation(program, "u_mode"), mode);
    m_gl.glUniform1ui(m_gl.glGetUniformLocation(program, "u_transformBase"),
                      GLuint(transformSlot * m_boneCount * doublesPerBone(m_method)));
    m_gl.glUniform1i(m_gl.glGetUniformLocation(program, "u_keepChain"), keepChain ? 1 : 0);
    m_gl.glUniform1i(m_gl.glGetUniformLocation(program, "u_writeScene"), writeScene ? 1 : 0);
    dispatchOverVertices(m_gl, program, m_vertexCount);
    // The next step reads the chain state this one wrote.
    m_gl.glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void GpuSkinning::skinRestToPose(GLuint program, std::size_t pose)
{
    const bool copy = pose == m_restPose && !m_restPoseMoves;
    uploadTransforms(copy ? std::vector<std::size_t>{} : std::vector<std::size_t>{pose});
    const int blend = m_method == SkinningMethod::Lbs ? kModeLbs : kModeDqs;
    runStep(program, copy ? kModeCopy : blend, 0, false, true);
    m_lastStepCount = copy ? 0 : 1;
}

void GpuSkinning::skinPoseToPose(GLuint program, std::size_t pose)
{
    const ChainWalk walk = walkTo(pose);
    if (walk.fromRest) {
        const auto bytes = GLsizeiptr(3 * m_vertexCount * sizeof(double));
        m_gl.glBindBuffer(GL_COPY_READ_BUFFER, m_rest.id());
        m_gl.glBindBuffer(GL_COPY_WRITE_BUFFER, m_chainState.id());
        m_gl.glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0, 0, bytes);
    }
    uploadTransforms(walk.steps);
    const int blend = m_method == SkinningMethod::Lbs ? kModeLbs : kModeDqs;
    if (walk.steps.empty())
        runStep(program, kModeCopy, 0, false, true);
    for (std::size_t i = 0; i < walk.steps.size(); ++i)
        runStep(program, blend, i, true, i + 1 == walk.steps.size());
    m_chainPose = pose;
    m_lastStepCount = walk.steps.size();
}

void GpuSkinning::skinPose(GpuScene& scene, std::size_t objectIndex, std::size_t pose)
{
    if (pose >= m_poseCount)
        throw std::invalid_argument("GPU skinning: pose " + std::to_string(pose) + " of a model with " +
                                    std::to_string(m_poseCount) + " poses.");
    const GpuObjectGeometry object = scene.objectGeometry(objectIndex);
    if (object.vertexCount != m_vertexCount || object.triangleCount != m_triangleCount)
        throw std::invalid_argument("GPU skinning: object " + std::to_string(objectIndex) + " has " +
                                    std::to_string(object.vertexCount) + " vertices and " +
                                    std::to_string(object.triangleCount) + " triangles, the model " +
                                    std::to_string(m_vertexCount) + " and " + std::to_string(m_triangleCount) + ".");
    const GLuint program = m_shaders->program(QStringLiteral("skinning"));
    const bool chained = m_chain == SkinningChain::PoseToPose;
    bindCommon(program, object, chained ? m_chainState.id() : m_rest.id());
    if (chained)
        skinPoseToPose(program, pose);
    else
        skinRestToPose(program, pose);
    m_normals.recompute(*m_shaders, object);
    // Everything that reads the scene next: the geometry passes (vertex attributes), the
    // resolve passes (storage), a read-back.
    m_gl.glMemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
                         GL_BUFFER_UPDATE_BARRIER_BIT);
}

} // namespace trimlab::render
