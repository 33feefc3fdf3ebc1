// The uploaded scene as shader storage (render/frame/gpu_scene.h), so a resolve pass can shade
// a stored fragment from its object and primitive id alone.

layout(std430, binding = STORAGE_SCENE_POSITIONS) readonly buffer ScenePositions { float scenePositions[]; };
layout(std430, binding = STORAGE_SCENE_NORMALS) readonly buffer SceneNormals { float sceneNormals[]; };
layout(std430, binding = STORAGE_SCENE_INDICES) readonly buffer SceneIndices { uint sceneIndices[]; };
// Optional per-vertex colors (e.g. a segmentation), RGBA8 packed; used when u_vertexColors.
layout(std430, binding = STORAGE_SCENE_COLORS) readonly buffer SceneColors { uint sceneColors[]; };

struct SceneObject {
    mat4 modelView;
    mat4 normalMatrix; // upper-left 3x3 is the inverse transpose of modelView's
    uint baseVertex;
    uint baseIndex;
    uint pad0;
    uint pad1;
};
layout(std430, binding = STORAGE_SCENE_OBJECTS) readonly buffer SceneObjects { SceneObject sceneObjects[]; };

uniform bool u_vertexColors;

vec3 scenePosition(uint v) { return vec3(scenePositions[3u * v], scenePositions[3u * v + 1u], scenePositions[3u * v + 2u]); }
vec3 sceneNormal(uint v) { return vec3(sceneNormals[3u * v], sceneNormals[3u * v + 1u], sceneNormals[3u * v + 2u]); }
vec3 sceneColor(uint v) { return unpackUnorm4x8(sceneColors[v]).rgb; }

// A point on a scene triangle, seen from the view: the triangle's vertices and the
// point's barycentric coordinates.
struct SurfacePoint {
    uint objectId;
    uvec3 vertices;
    vec3 barycentric;
    vec3 faceNormal; // view space, not normalised: (b - a) x (c - a)
};

// The view-space point `p` on primitive `primitiveId` of object `objectId`.
SurfacePoint surfacePoint(uint objectId, uint primitiveId, vec3 p)
{
    SceneObject object = sceneObjects[objectId];
    uint first = object.baseIndex + 3u * primitiveId;
    uvec3 v = uvec3(sceneIndices[first], sceneIndices[first + 1u], sceneIndices[first + 2u]) + uvec3(object.baseVertex);
    vec3 a = (object.modelView * vec4(scenePosition(v.x), 1.0)).xyz;
    vec3 b = (object.modelView * vec4(scenePosition(v.y), 1.0)).xyz;
    vec3 c = (object.modelView * vec4(scenePosition(v.z), 1.0)).xyz;
    vec3 n = cross(b - a, c - a);
    float area2 = dot(n, n);
    vec3 bary = vec3(1.0 / 3.0);
    if (area2 > 0.0) {
        bary.y = dot(cross(p - a, c - a), n) / area2;
        bary.z = dot(cross(b - a, p - a), n) / area2;
        bary.x = 1.0 - bary.y - bary.z;
        bary = clamp(bary, 0.0, 1.0);
    }
    return SurfacePoint(objectId, v, bary, n);
}

// Smooth view-space normal at the point (barycentric interpolation of vertex normals).
vec3 interpolatedViewNormal(SurfacePoint s)
{
    mat3 normalMatrix = mat3(sceneObjects[s.objectId].normalMatrix);
    vec3 n = normalMatrix * (s.barycentric.x * sceneNormal(s.vertices.x) + s.barycentric.y * sceneNormal(s.vertices.y) +
                             s.barycentric.z * sceneNormal(s.vertices.z));
    return normalize(dot(n, n) > 0.0 ? n : s.faceNormal);
}

vec3 interpolatedColor(SurfacePoint s)
{
    return s.barycentric.x * sceneColor(s.vertices.x) + s.barycentric.y * sceneColor(s.vertices.y) +
           s.barycentric.z * sceneColor(s.vertices.z);
}
