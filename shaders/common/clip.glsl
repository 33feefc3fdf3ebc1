// The clipping planes in view space (up to six: core/trim/clip_set.h), which fragments
// count toward the winding index at the start of a pixel's kept span
// (core/trim/clip_plane.h explains the span), and the span itself for the resolve passes.

const int MAX_CLIP_PLANES = 6;

uniform int u_clipCount;                        // enabled planes, packed first
uniform vec4 u_clipPlanesView[MAX_CLIP_PLANES]; // (n, d) in view space; kept where dot(n, p) + d >= 0
uniform int u_clipSlot[MAX_CLIP_PLANES];        // the ClipSet index (0..5) of each packed plane
uniform float u_zNear;
uniform float u_zFar;

// `precise`: a count pass and a later store pass must classify every fragment alike.
bool clipPlaneKeeps(int plane, vec3 viewPos)
{
    precise float side = dot(u_clipPlanesView[plane].xyz, viewPos) + u_clipPlanesView[plane].w;
    return side >= 0.0;
}

// True when every enabled plane keeps `viewPos`: the fragment lies in its pixel's span.
bool clipKeeps(vec3 viewPos)
{
    for (int i = 0; i < u_clipCount; ++i)
        if (!clipPlaneKeeps(i, viewPos))
            return false;
    return true;
}

// True when a fragment at `viewPos` lies behind the start of its pixel's kept span. The
// start is the farthest of the near plane and the planes the ray enters (those that do
// not keep the ray's near point); a fragment is behind it iff each such plane keeps it.
// With one plane: kept, or the ray starts (at the near plane) on the kept side.
bool behindSpanStart(vec3 viewPos)
{
    vec3 nearPoint = viewPos * (u_zNear / -viewPos.z);
    for (int i = 0; i < u_clipCount; ++i)
        if (!clipPlaneKeeps(i, viewPos) && !clipPlaneKeeps(i, nearPoint))
            return false;
    return true;
}

// The kept span of the pixel ray with view-space `direction` (z = -1, so t is the view
// depth), as keptSpan(ClipSet) computes it in double precision on the CPU.
struct ClipSpan {
    bool empty;
    float tStart;
    float tEnd;
    int startSlot; // ClipSet index of the plane at tStart; -1: the near plane
};

ClipSpan pixelSpan(vec3 direction)
{
    ClipSpan span = ClipSpan(false, u_zNear, u_zFar, -1);
    for (int i = 0; i < u_clipCount; ++i) {
        float slope = dot(u_clipPlanesView[i].xyz, direction);
        float offset = u_clipPlanesView[i].w; // the eye is the view-space origin
        float fNear = offset + slope * u_zNear;
        float fFar = offset + slope * u_zFar;
        if (fNear >= 0.0 && fFar >= 0.0)
            continue;
        if (fNear < 0.0 && fFar < 0.0)
            return ClipSpan(true, 0.0, 0.0, -1);
        float t = clamp(-offset / slope, u_zNear, u_zFar);
        if (fNear >= 0.0) {
            span.tEnd = min(span.tEnd, t);
        } else if (span.startSlot < 0 || t > span.tStart) {
            span.tStart = t;
            span.startSlot = u_clipSlot[i];
        }
    }
    span.empty = span.tStart > span.tEnd;
    return span;
}
