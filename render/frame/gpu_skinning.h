#pragma once
/// \file
/// Skinned poses evaluated on the GPU, written straight into an object of a GpuScene: the
/// compute pass shaders/skinning.comp evaluates a SkinningModel (core/skinning/) pose by
/// pose, then shaders/vertex_normals.comp recomputes the object's normals
/// (gpu_vertex_normals.h), so a pose costs no vertex upload and no CPU work per vertex.
/// The CPU's skinning_reconstruction.h stays the reference; the GPU evaluates the same
/// formulas (thesis eq. 4.7 / 4.8) in the same order.
///
/// What lives on the GPU, uploaded once: the rest positions, the influences (per vertex the
/// count, its bones and weights, in as many slots as the model's largest count — 4 for the
/// usual fits, up to kMaxInfluences = 8, which glTF skins carry as two joint sets; reading
/// a fixed 4 would drop a real model's influences, a fixed 8 would double the bandwidth of
/// the usual one) and the one-ring for the normals. What is uploaded per evaluation: the
/// bone transforms of the poses it applies, B affine matrices (LBS, 12 doubles each) or B
/// unit dual quaternions (DQS, 8 doubles) per pose.
///
/// The two chains:
/// - RestToPose: pose t is the blend of pose t's transforms applied to the rest positions.
///   Any pose in any order costs one pass.
/// - PoseToPose (the thesis's p2p-skinning): transforms[t] map pose previousPose(t) to pose
///   t, blended per vertex, so they do not compose into one transform per bone. The GPU
///   keeps the positions of the last pose it evaluated (the chain state) and walks the
///   chain from there: playing forward (or backward before the rest pose) applies one step
///   per pose; a pose behind the state (scrubbing back towards the rest pose) restarts
///   from the rest positions and applies every step up to it (chainOrder's path), all on
///   the GPU. Asking for the state's pose again only copies it.
///
/// Precision: the blends, the chain state and the rest positions are doubles on the GPU
/// (GL 4.0 core), as on the CPU, so a long chain does not drift from the reference; only
/// the positions written into the scene are rounded to float, as updatePositions rounds
/// them. Double arithmetic is slow on consumer GPUs, but a pass is a few dozen operations
/// per influence — far from mattering beside the trim.

#include "render/frame/gpu_scene.h"
#include "render/frame/gpu_vertex_normals.h"
#include "render/gl/gl_functions.h"
#include "render/gl/gl_objects.h"
#include "render/gl/shader_library.h"

#include "core/skinning/skinning_model.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

namespace trimlab::render {

class GpuSkinning {
public:
    /// Uploads what every pose of `model` shares and keeps its transforms for the passes.
    /// The context must be current (also at destruction). Throws std::invalid_argument for
    /// a model without poses, weights not one per rest position, an influence count outside
    /// 1…kMaxInfluences, a bone ≥ boneCount or transforms not #P × B; GpuMemoryError;
    /// ShaderBuildError.
    GpuSkinning(GlFunctions& gl, const SkinningModel& model);
    ~GpuSkinning();
    GpuSkinning(const GpuSkinning&) = delete;
    GpuSkinning& operator=(const GpuSkinning&) = delete;

    /// Writes pose `pose` into object `objectIndex` of `scene` — positions, then normals —
    /// and orders it before the scene's next draw, storage read or buffer read. The object
    /// must be the model's mesh (same vertex and triangle counts). Throws
    /// std::invalid_argument for a pose ≥ #P or an object that does not match.
    void skinPose(GpuScene& scene, std::size_t objectIndex, std::size_t pose);

    /// The pose held in the pose-to-pose chain state (nullopt: none yet, or RestToPose).
    [[nodiscard]] std::optional<std::size_t> chainPose() const { return m_chainPose; }
    /// How many poses' transforms the last skinPose applied: 1 for a rest-to-pose pose or a
    /// step of playback, the path length when a chain walk restarted at the rest pose, 0
    /// when it only copied positions.
    [[nodiscard]] std::size_t lastStepCount() const { return m_lastStepCount; }
    /// GPU memory held: rest positions, influences, chain state, transforms, one-ring.
    [[nodiscard]] std::size_t memoryBytes() const;

private:
    struct ChainWalk {
        bool fromRest = true;           ///< reset the chain state to the rest positions first
        std::vector<std::size_t> steps; ///< the poses whose transforms apply, in order
    };
    [[nodiscard]] ChainWalk walkTo(std::size_t pose) const;
    void uploadTransforms(const std::vector<std::size_t>& poses);
    void bindCommon(GLuint program, const GpuObjectGeometry& object, GLuint source);
    void runStep(GLuint program, int mode, std::size_t transformSlot, bool keepChain, bool writeScene);
    void skinRestToPose(GLuint program, std::size_t pose);
    void skinPoseToPose(GLuint program, std::size_t pose);

    GlFunctions& m_gl;
    std::unique_ptr<ShaderLibrary> m_shaders;
    SkinningMethod m_method;
    SkinningChain m_chain;
    std::size_t m_restPose;
    bool m_restPoseMoves;
    std::size_t m_vertexCount;
    std::size_t m_triangleCount;
    std::size_t m_boneCount;
    std::size_t m_poseCount;
    std::size_t m_stride;                 ///< influence slots per vertex
    std::vector<double> m_poseTransforms; ///< #P × B × (12 or 8), the upload's layout
    GlBuffer m_rest;
    GlBuffer m_influences;
    GlBuffer m_weights;
    GlBuffer m_chainState; ///< PoseToPose only
    GlBuffer m_transforms;
    std::size_t m_transformsBytes = 0;
    GpuVertexNormals m_normals;
    std::optional<std::size_t> m_chainPose;
    std::size_t m_lastStepCount = 0;
    std::size_t m_sharedBytes = 0;
};

} // namespace trimlab::render
