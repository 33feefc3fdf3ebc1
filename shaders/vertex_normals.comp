#version 430 core
// Angle-weighted vertex normals of one object, recomputed from the scene's positions after a
// GPU pass moved them (render/frame/gpu_vertex_normals.h): the normals of vertexNormals in
// core/mesh/triangle_mesh.cpp. Each invocation owns one vertex and walks its one-ring (the
// corners of the triangles around it, in triangle order), so the sum needs no atomics and is
// the same on every run.

layout(local_size_x = 64) in;

layout(std430, binding = STORAGE_SCENE_POSITIONS) readonly buffer ScenePositions { float scenePositions[]; };
layout(std430, binding = STORAGE_SCENE_NORMALS) writeonly buffer SceneNormals { float sceneNormals[]; };
// [0, #V]: each vertex's first corner (CSR offsets); from u_cornersStart: corners as
// triangle·3 + corner; from u_trianglesStart: three object-local vertices per triangle.
layout(std430, binding = STORAGE_VERTEX_RING) readonly buffer VertexRing { uint ring[]; };

uniform uint u_vertexCount;
uniform uint u_firstVertex; // of this dispatch: large meshes take several
uniform uint u_baseVertex;  // the object's first vertex in the scene's buffers
uniform uint u_cornersStart;
uniform uint u_trianglesStart;

dvec3 position(uint v)
{
    uint s = 3u * (u_baseVertex + v);
    return dvec3(scenePositions[s], scenePositions[s + 1u], scenePositions[s + 2u]);
}

// sin and cos of x in [0, π/2] (a little beyond is fine) in double precision: their Taylor
// series to x^25/25! and x^24/24!, below 1e-19 there, nested (Horner) and without a loop
// (llvmpipe notes: a shader's loop iterations are counted together). The ratios of
// consecutive terms are double constants (an unsuffixed GLSL literal is a float; 1/6 is not
// exact in float), multiplied rather than divided by.
dvec2 sinCos(double x)
{
    double y = x * x;
    double s = 1.0 - y * (1.0lf / 506.0lf) * (1.0 - y * (1.0lf / 600.0lf));
    s = 1.0 - y * (1.0lf / 342.0lf) * (1.0 - y * (1.0lf / 420.0lf) * s);
    s = 1.0 - y * (1.0lf / 210.0lf) * (1.0 - y * (1.0lf / 272.0lf) * s);
    s = 1.0 - y * (1.0lf / 110.0lf) * (1.0 - y * (1.0lf / 156.0lf) * s);
    s = 1.0 - y * (1.0lf / 42.0lf) * (1.0 - y * (1.0lf / 72.0lf) * s);
    s = x * (1.0 - y * (1.0lf / 6.0lf) * (1.0 - y * (1.0lf / 20.0lf) * s));
    double c = 1.0 - y * (1.0lf / 462.0lf) * (1.0 - y * (1.0lf / 552.0lf));
    c = 1.0 - y * (1.0lf / 306.0lf) * (1.0 - y * (1.0lf / 380.0lf) * c);
    c = 1.0 - y * (1.0lf / 182.0lf) * (1.0 - y * (1.0lf / 240.0lf) * c);
    c = 1.0 - y * (1.0lf / 90.0lf) * (1.0 - y * (1.0lf / 132.0lf) * c);
    c = 1.0 - y * (1.0lf / 30.0lf) * (1.0 - y * (1.0lf / 56.0lf) * c);
    c = 1.0 - y * (1.0lf / 2.0lf) * (1.0 - y * (1.0lf / 12.0lf) * c);
    return dvec2(s, c);
}

// The angle of (cosine, sine) = (c, s), s ≥ 0, in double precision. GLSL has trigonometry in
// float only, and a float angle is not enough: where a vertex's weighted face normals
// nearly cancel (a crumpled pose), the normal amplifies the weights' errors hundreds of
// times. So the float atan is a first guess θ0, and the small angle between (c, s) and
// (cos θ0, sin θ0), tan r = y / x, corrects it (r ≈ y / x to r³/3, below 1e-15 for any
// float atan good to 1e-5).
double angleOf(double c, double s)
{
    double guess = double(atan(float(s), float(c)));
    dvec2 halfAngle = sinCos(0.5 * guess); // θ0 / 2 lies in [0, π/2]
    double sin0 = 2.0 * halfAngle.x * halfAngle.y;
    double cos0 = halfAngle.y * halfAngle.y - halfAngle.x * halfAngle.x;
    double y = s * cos0 - c * sin0;
    double x = c * cos0 + s * sin0;
    return guess + y / x;
}

// The interior angle at a of triangle (a, b, c), 0 at a degenerate corner: cornerAngle's
// acos of the cosine, here from the cosine and the sine.
double cornerAngle(dvec3 a, dvec3 b, dvec3 c)
{
    dvec3 u = b - a;
    dvec3 w = c - a;
    double lengths = length(u) * length(w);
    if (lengths == 0.0)
        return 0.0;
    return angleOf(clamp(dot(u, w) / lengths, -1.0, 1.0), length(cross(u, w)) / lengths);
}

void main()
{
    uint v = u_firstVertex + gl_GlobalInvocationID.x;
    if (v >= u_vertexCount)
        return;
    dvec3 sum = dvec3(0.0);
    for (uint k = ring[v]; k < ring[v + 1u]; ++k) {
        uint corner = ring[u_cornersStart + k];
        uint t = u_trianglesStart + 3u * (corner / 3u);
        uint i = corner % 3u;
        dvec3 p[3] = dvec3[3](position(ring[t]), position(ring[t + 1u]), position(ring[t + 2u]));
        dvec3 n = cross(p[1] - p[0], p[2] - p[0]);
        double len = length(n);
        if (len == 0.0 || isinf(len) || isnan(len))
            continue;
        sum += (n / len) * cornerAngle(p[i], p[(i + 1u) % 3u], p[(i + 2u) % 3u]);
    }
    double len = length(sum);
    vec3 normal = len > 0.0 ? vec3(sum / len) : vec3(0.0);
    uint s = 3u * (u_baseVertex + v);
    sceneNormals[s] = normal.x;
    sceneNormals[s + 1u] = normal.y;
    sceneNormals[s + 2u] = normal.z;
}
