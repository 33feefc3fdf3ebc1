#version 430 core
// One skinning step of a SkinningModel (render/frame/gpu_skinning.h): every invocation moves
// one vertex from the source positions by the blend of its bones' transforms, the same
// formulas as core/skinning/skinning_reconstruction.cpp (thesis eq. 4.7 / 4.8), and writes
// the result into the scene's position buffer. The arithmetic is in double precision, like
// the CPU's: a pose-to-pose chain feeds each step's result to the next, and float rounding
// would accumulate along it.

layout(local_size_x = 64) in;

// The positions the step acts on: the rest pose, or the last pose of a pose-to-pose chain,
// which the step then replaces (u_keepChain). xyz per vertex.
layout(std430, binding = STORAGE_SKINNING_SOURCE) buffer SkinningSource { double sourcePositions[]; };
// Per vertex u_stride + 1 entries: the influence count, then the bones (unused ones 0).
layout(std430, binding = STORAGE_SKINNING_INFLUENCES) readonly buffer SkinningInfluences { uint influences[]; };
// Per vertex u_stride weights, in the order of its bones.
layout(std430, binding = STORAGE_SKINNING_WEIGHTS) readonly buffer SkinningWeights { double weights[]; };
// Per bone 12 doubles for LBS (the linear part column by column, then the translation) or
// 8 for DQS (real part x y z w, then dual part x y z w).
layout(std430, binding = STORAGE_SKINNING_TRANSFORMS) readonly buffer SkinningTransforms { double transforms[]; };
layout(std430, binding = STORAGE_SCENE_POSITIONS) writeonly buffer ScenePositions { float scenePositions[]; };

const int kModeCopy = 0; // the source as it is: the rest pose, or a chain pose asked for again
const int kModeLbs = 1;
const int kModeDqs = 2;

uniform uint u_vertexCount;
uniform uint u_firstVertex; // of this dispatch: large meshes take several
uniform uint u_sceneBaseVertex;
uniform uint u_stride;
uniform uint u_transformBase; // the first bone's transform of the pose applied, in transforms
uniform int u_mode;
uniform bool u_keepChain;
uniform bool u_writeScene;

dvec3 sourcePosition(uint v)
{
    return dvec3(sourcePositions[3u * v], sourcePositions[3u * v + 1u], sourcePositions[3u * v + 2u]);
}

// Σ_i w_i Q_i applied to p, accumulated bone by bone in influence order (weightedSum).
dvec3 linearBlend(uint v, dvec3 p)
{
    uint record = v * (u_stride + 1u);
    uint count = influences[record];
    dmat3 linear = dmat3(0.0);
    dvec3 translation = dvec3(0.0);
    for (uint i = 0u; i < count; ++i) {
        uint t = u_transformBase + 12u * influences[record + 1u + i];
        double w = weights[v * u_stride + i];
        dmat3 q = dmat3(transforms[t], transforms[t + 1u], transforms[t + 2u], transforms[t + 3u], transforms[t + 4u],
                        transforms[t + 5u], transforms[t + 6u], transforms[t + 7u], transforms[t + 8u]);
        linear += w * q;
        translation += w * dvec3(transforms[t + 9u], transforms[t + 10u], transforms[t + 11u]);
    }
    return linear * p + translation;
}

dvec4 realPart(uint bone)
{
    uint t = u_transformBase + 8u * bone;
    return dvec4(transforms[t], transforms[t + 1u], transforms[t + 2u], transforms[t + 3u]);
}

dvec4 dualPart(uint bone)
{
    uint t = u_transformBase + 8u * bone + 4u;
    return dvec4(transforms[t], transforms[t + 1u], transforms[t + 2u], transforms[t + 3u]);
}

// The rotation matrix of a unit quaternion q = (x, y, z, w).
dmat3 rotationMatrix(dvec4 q)
{
    double xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
    double xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
    double wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
    return dmat3(1.0 - 2.0 * (yy + zz), 2.0 * (xy + wz), 2.0 * (xz - wy),  // column 0
                 2.0 * (xy - wz), 1.0 - 2.0 * (xx + zz), 2.0 * (yz + wx),  // column 1
                 2.0 * (xz + wy), 2.0 * (yz - wx), 1.0 - 2.0 * (xx + yy)); // column 2
}

// Dual quaternion blending as blendDualQuaternions (core/skinning/dual_quaternion.h): each
// influence takes the sign whose real part agrees with the largest-weight influence's (the
// first: weights are sorted), the sum is normalised — unit real part, dual part made
// orthogonal to it, a zero or non-finite real part giving the identity — and the rigid
// matrix [R | 2·(q_d q_r*)] is applied to p.
dvec3 dualQuaternionBlend(uint v, dvec3 p)
{
    uint record = v * (u_stride + 1u);
    uint count = influences[record];
    dvec4 pivot = realPart(influences[record + 1u]);
    dvec4 real = dvec4(0.0);
    dvec4 dual = dvec4(0.0);
    for (uint i = 0u; i < count; ++i) {
        uint bone = influences[record + 1u + i];
        dvec4 r = realPart(bone);
        double signedWeight = (dot(r, pivot) < 0.0 ? -1.0 : 1.0) * weights[v * u_stride + i];
        real += r * signedWeight;
        dual += dualPart(bone) * signedWeight;
    }
    double length = sqrt(dot(real, real));
    if (!(length > 0.0) || isinf(length) || isnan(length))
        return p; // the identity
    double inverse = 1.0 / length;
    real *= inverse;
    dual *= inverse;
    dual -= real * dot(real, dual);
    // The vector part of q_d·conj(q_r), twice: the translation (translationOf).
    dvec3 translation = 2.0 * (real.w * dual.xyz - dual.w * real.xyz + cross(real.xyz, dual.xyz));
    return rotationMatrix(real) * p + translation;
}

void main()
{
    uint v = u_firstVertex + gl_GlobalInvocationID.x;
    if (v >= u_vertexCount)
        return;
    dvec3 p = sourcePosition(v);
    if (u_mode == kModeLbs)
        p = linearBlend(v, p);
    else if (u_mode == kModeDqs)
        p = dualQuaternionBlend(v, p);
    if (u_keepChain) {
        sourcePositions[3u * v] = p.x;
        sourcePositions[3u * v + 1u] = p.y;
        sourcePositions[3u * v + 2u] = p.z;
    }
    if (u_writeScene) {
        uint s = 3u * (u_sceneBaseVertex + v);
        scenePositions[s] = float(p.x);
        scenePositions[s + 1u] = float(p.y);
        scenePositions[s + 2u] = float(p.z);
    }
}
