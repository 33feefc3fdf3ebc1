// The uploaded scene as shader storage (render/gpu_scene.h), so a resolve pass can shade
// a stored fragment from its object and primitive id alone.

layout(std430, binding = 1) readonly buffer ScenePositions { float scenePositions[]; };
layout(std430, binding = 2) readonly buffer SceneNormals { float sceneNormals[]; };
layout(std430, binding = 3) readonly buffer SceneIndices { uint sceneIndices[]; };

struct SceneObject {
    mat4 modelView;
    mat4 normalMatrix; // upper-left 3x3 is the inverse transpose of modelView's
    uint baseVertex;
    uint baseIndex;
    uint pad0;
    uint pad1;
};
layout(std430, binding = 4) readonly buffer SceneObjects { SceneObject sceneObjects[]; };

vec3 scenePosition(uint v) { return vec3(scenePositions[3u * v], scenePositions[3u * v + 1u], scenePositions[3u * v + 2u]); }
vec3 sceneNormal(uint v) { return vec3(sceneNormals[3u * v], sceneNormals[3u * v + 1u], sceneNormals[3u * v + 2u]); }

// Smooth view-space normal of primitive `primitiveId` of object `objectId` at the
// view-space point `p` on it (barycentric interpolation of the vertex normals).
vec3 interpolatedViewNormal(uint objectId, uint primitiveId, vec3 p)
{
    SceneObject object = sceneObjects[objectId];
    uvec3 v = uvec3(sceneIndices[object.baseIndex + 3u * primitiveId],
                    sceneIndices[object.baseIndex + 3u * primitiveId + 1u],
                    sceneIndices[object.baseIndex + 3u * primitiveId + 2u]) + uvec3(object.baseVertex);
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
    mat3 normalMatrix = mat3(object.normalMatrix);
    vec3 smoothNormal = normalMatrix * (bary.x * sceneNormal(v.x) + bary.y * sceneNormal(v.y) + bary.z * sceneNormal(v.z));
    if (dot(smoothNormal, smoothNormal) == 0.0)
        smoothNormal = n;
    return normalize(smoothNormal);
}
