// Capping (core/trim/trim_walk.h, "Capping"; thesis 8.1.2, Fig. 8.14): where the pixel's
// kept span starts at a clipping plane and the point there classifies interior, the pixel
// shows that plane's cap, lit flat with the plane's normal and patterned in world space
// (CPU twin: core/trim/trim_shading.h, shadeCap; keep the two identical).
// Needs frame_counters.glsl, trim_shading.glsl and trim_output.glsl.

#include "common/clip.glsl"

const int CAP_HATCHED = 0;
const int CAP_STRIPED = 1;
const int CAP_SOLID = 2;
const float CAP_LINE_SHADE = 0.45;

uniform int u_capPattern;
uniform float u_capSpacing;   // world units between lines; <= 0: solid
uniform float u_capLineWidth; // fraction of the spacing, in [0, 1]
uniform mat4 u_viewToWorld;
uniform vec3 u_capNormalsWorld[MAX_CLIP_PLANES]; // unit world normal of each ClipSet plane

// The plane's pattern basis, from its normal alone (capPatternBasis).
void capPatternBasis(vec3 n, out vec3 u, out vec3 v)
{
    vec3 a = abs(n);
    vec3 axis = a.x <= a.y && a.x <= a.z ? vec3(1.0, 0.0, 0.0) : (a.y <= a.z ? vec3(0.0, 1.0, 0.0) : vec3(0.0, 0.0, 1.0));
    u = normalize(cross(n, axis));
    v = cross(n, u);
}

bool onCapLine(vec3 p, vec3 n)
{
    if (u_capPattern == CAP_SOLID || !(u_capSpacing > 0.0))
        return false;
    vec3 u;
    vec3 v;
    capPatternBasis(n, u, v);
    if (u_capPattern == CAP_STRIPED)
        return fract(dot(p, u) / u_capSpacing) < u_capLineWidth;
    float diagonal = u_capSpacing * sqrt(2.0);
    return fract(dot(p, u + v) / diagonal) < u_capLineWidth || fract(dot(p, u - v) / diagonal) < u_capLineWidth;
}

// Emits the cap and returns true when the pixel shows one (`startInterior`: the
// classification at the span start).
bool emitCapIfShown(bool startInterior, int windingAtStart, bool overflowed)
{
    if (!startInterior)
        return false;
    vec3 direction = pixelRayDirection();
    ClipSpan span = pixelSpan(direction);
    if (span.empty || span.startSlot < 0)
        return false;
    vec3 viewPos = direction * span.tStart;
    vec3 p = (u_viewToWorld * vec4(viewPos, 1.0)).xyz;
    vec3 n = u_capNormalsWorld[span.startSlot];
    vec3 toViewer = mat3(u_viewToWorld) * normalize(-viewPos);
    vec3 base = onCapLine(p, n) ? CAP_LINE_SHADE * FRONT_FACING_COLOR : FRONT_FACING_COLOR;
    o_color = vec4(base * (AMBIENT + (1.0 - AMBIENT) * abs(dot(n, toViewer))), 1.0);
    uint flags = (uint(span.startSlot + 1) << INFO_CAP_SHIFT) | (overflowed ? INFO_OVERFLOWED : 0u);
    o_info = uvec4(0u, flags, floatBitsToUint(span.tStart), uint(windingAtStart));
    gl_FragDepth = windowDepth(viewPos);
    atomicCounterIncrement(u_capPixels);
    return true;
}
