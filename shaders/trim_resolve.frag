#version 430 core
// Resolve pass of the k+-buffer for static rules (thesis Algorithm 7.8 RESOLVE with
// the trimming of 8.1.2): sort the pixel's stored fragments, then walk them front to
// back from the winding index at the span start; the first fragment whose two sides
// classify differently is the trim point shown. The CPU twin is core/trim/trim_walk.
//
// A pixel that overflowed (more than k fragments) is still exact when its trim point is
// among the k nearest. Otherwise it is "unresolved": counted and painted
// UNRESOLVED_COLOR, never silently shown wrong.

#define KPLUS_ACCESS readonly
#include "common/kplus_images.glsl"
#include "common/fragment_pack.glsl"
#include "common/static_rule.glsl"
#include "common/trim_shading.glsl"
#include "common/scene_data.glsl"
#include "common/trim_output.glsl"

#ifndef K_MAX
#error K_MAX (the k of the k+-buffer) must be defined
#endif
uvec2 g_fragments[K_MAX];
#include "common/fragment_sort.glsl"

uniform bool u_trimEnabled;
uniform int u_rule;
uniform vec2 u_viewportSize;
uniform vec2 u_tanHalfFov; // (tan(fovx/2), tan(fovy/2))

// View-space direction of this pixel's ray, scaled to z = -1 (so point = dir * depth).
vec3 pixelRayDirection()
{
    vec2 ndc = gl_FragCoord.xy / u_viewportSize * 2.0 - 1.0;
    return vec3(ndc * u_tanHalfFov, -1.0);
}

// Index of the shown fragment in the sorted g_fragments, or -1.
int findTrimFragment(int count, int windingAtStart)
{
    int w = windingAtStart;
    for (int i = 0; i < count; ++i) {
        int wAfter = w + (fragmentFrontFacing(g_fragments[i]) ? 1 : -1);
        if (!u_trimEnabled || isTrimBoundary(u_rule, w, wAfter))
            return i;
        w = wAfter;
    }
    return -1;
}

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    int count = int(min(imageLoad(u_counter, pixel).r, uint(K_MAX)));
    for (int i = 0; i < count; ++i)
        g_fragments[i] = imageLoad(u_fragments, ivec3(pixel, i)).xy;
    sortFragments(count);

    int windingAtStart = imageLoad(u_winding, pixel).r;
    bool overflowed = imageLoad(u_overflow, pixel).r != 0u;
    int shown = findTrimFragment(count, windingAtStart);
    if (overflowed)
        atomicCounterIncrement(u_overflowPixels);

    uint flags = overflowed ? INFO_OVERFLOWED : 0u;
    if (shown < 0) {
        bool unresolved = overflowed;
        if (unresolved)
            atomicCounterIncrement(u_unresolvedPixels);
        o_color = vec4(unresolved ? UNRESOLVED_COLOR : BACKGROUND_COLOR, 1.0);
        o_info = uvec4(0u, flags | (unresolved ? INFO_UNRESOLVED : 0u),
                       0x7F800000u /* +inf */, uint(windingAtStart));
        gl_FragDepth = 1.0;
        return;
    }
    uvec2 f = g_fragments[shown];
    bool front = fragmentFrontFacing(f);
    vec3 viewPos = pixelRayDirection() * fragmentDepth(f);
    vec3 normal = interpolatedViewNormal(fragmentObject(f), fragmentPrimitive(f), viewPos);
    o_color = vec4(shadeTrimPoint(front, normal, normalize(-viewPos)), 1.0);
    flags |= fragmentObject(f) | (front ? INFO_FRONT_FACING : INFO_BACK_FACING);
    o_info = uvec4(fragmentPrimitive(f) + 1u, flags, f.x, uint(windingAtStart));
    gl_FragDepth = windowDepth(viewPos);
}
