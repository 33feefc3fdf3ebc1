#pragma once
/// \file
/// Every binding point TrimLab's programs share, in one place: the image units and
/// shader storage blocks of the multi-fragment methods, the scene's storage blocks
/// (frame/gpu_scene.h) and the frame counters' atomic counter buffer
/// (frame/frame_counters.h). The GLSL side never spells a number: ShaderLibrary
/// assembles every stage with glslBindingDefines() after its #version line
/// (shader_source.h), so `layout(binding = IMAGE_COUNTER)` in a shader and
/// binding::kCounterImage here are the same value by construction.

#include <QStringList>
#include <QtGui/qopengl.h>

namespace trimlab::render::binding {

// Image units: a method binds only those it uses; the numbers never change meaning.
inline constexpr GLuint kCounterImage = 0;   ///< r32ui: fragments counted or held per pixel
inline constexpr GLuint kSemaphoreImage = 1; ///< r32ui: per-pixel spin-lock (0 = free)
inline constexpr GLuint kWindingImage = 2;   ///< r32i: winding index at the start of the kept span
inline constexpr GLuint kOverflowImage = 3;  ///< r32ui: 1 once a pixel lost fragments to a capacity limit
inline constexpr GLuint kFragmentsImage = 4; ///< rg32ui 2D array: per-pixel fragment slots (k⁺, AB_FP)
inline constexpr GLuint kHeadImage = 5;      ///< r32ui: head/offset into a node buffer (AB_LL, S-buffer, K⁺B-SB)
inline constexpr GLuint kPeelDepthImage = 6; ///< r32ui 2D array: peeling cursor, one field per layer
inline constexpr GLuint kWalkImage = 7;      ///< rgba32ui 2D array: trim walks carried between peeling passes

// Shader storage blocks: the scene's (GpuScene) ...
inline constexpr GLuint kSceneColorsStorage = 0;    ///< uint colors[]: optional per-vertex RGBA8
inline constexpr GLuint kScenePositionsStorage = 1; ///< float positions[]: xyz per vertex
inline constexpr GLuint kSceneNormalsStorage = 2;   ///< float normals[]: xyz per vertex
inline constexpr GLuint kSceneIndicesStorage = 3;   ///< uint indices[]: three per triangle
inline constexpr GLuint kSceneObjectsStorage = 4;   ///< SceneObject objects[]: matrices and offsets
// ... and the methods'.
inline constexpr GLuint kNodesStorage = 5;                 ///< uvec2 nodes[] of node-buffer methods
inline constexpr GLuint kLinksStorage = 6;                 ///< uint next[] of linked lists
inline constexpr GLuint kSharedCountersStorage = 7;        ///< S-buffer's memory referencing; AB_LL's node counter
inline constexpr GLuint kDynamicStateStorage = 8;          ///< dynamic rules: per-pixel reference index
inline constexpr GLuint kReferenceBitsStorage = 9;         ///< dynamic rules: the reference frame's bit vectors
inline constexpr GLuint kCharacterizationBitsStorage = 10; ///< dynamic rules: the bit vectors a level writes
inline constexpr GLuint kObjectWindingsStorage = 11;       ///< CSG, collisions: per-object winding per pixel
// ... and the compute passes that rewrite an object's geometry in place (frame/gpu_skinning.h,
// frame/gpu_vertex_normals.h), which bind the scene's positions and normals beside these.
inline constexpr GLuint kSkinningSourceStorage = 12;     ///< double positions[]: the rest pose or the chain's last pose
inline constexpr GLuint kSkinningInfluencesStorage = 13; ///< uint: per vertex the count, then its bones
inline constexpr GLuint kSkinningWeightsStorage = 14;    ///< double weights[]: per vertex, beside its bones
inline constexpr GLuint kSkinningTransformsStorage = 15; ///< double: the bone transforms of the poses applied
inline constexpr GLuint kVertexRingStorage = 16;         ///< uint: CSR one-ring (offsets, corners, triangles)

// Atomic counter buffers.
inline constexpr GLuint kFrameCountersAtomic = 0; ///< the per-frame statistics (frame_counters.glsl)

/// "IMAGE_COUNTER 0", … "STORAGE_SCENE_POSITIONS 1", … "ATOMIC_FRAME_COUNTERS 0": every
/// binding above as a GLSL #define, under the name the shaders use.
[[nodiscard]] QStringList glslBindingDefines();

} // namespace trimlab::render::binding
