// The winding index at the start of each pixel's kept span, counted exactly in a geometry
// pass from the far side (core/trim/clip_plane.h explains why): every fragment behind the
// span start adds +1 if back-facing, -1 if front-facing. Every method counts it this way,
// whatever it stores, so the index never depends on storage capacity.
// Needs clip.glsl and bindings.glsl; the includer declares u_winding's access.

layout(binding = IMAGE_WINDING, r32i) uniform coherent iimage2D u_winding;

// Adds this fragment's facing when it lies behind the span start; returns whether the
// fragment is inside the kept span (the ones a method stores).
bool countWinding(ivec2 pixel, vec3 viewPos)
{
    bool kept = clipKeeps(viewPos);
    if (kept || rayStartsAtNear(viewPos))
        imageAtomicAdd(u_winding, pixel, gl_FrontFacing ? -1 : 1);
    return kept;
}
