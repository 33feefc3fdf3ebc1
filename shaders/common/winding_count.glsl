// The winding index at the start of each pixel's kept span, counted exactly in a geometry
// pass from the far side (core/trim/clip_plane.h explains why): every fragment behind the
// span start adds +1 if back-facing, -1 if front-facing. Every method counts it this way,
// whatever it stores, so the index never depends on storage capacity. With
// OBJECT_WINDINGS the same fragments also count toward their object's own index
// (object_windings.glsl), for CSG and collision highlighting.
// Needs clip.glsl; the includer declares u_winding's access.

layout(binding = IMAGE_WINDING, r32i) uniform coherent iimage2D u_winding;

uniform uint u_objectId; // the object being drawn (GpuScene::draw sets it)

#ifdef DYNAMIC_RULES
#include "common/dynamic_state.glsl"
#endif
#ifdef OBJECT_WINDINGS
#define OBJECT_WINDINGS_ACCESS coherent
#include "common/object_windings.glsl"
#endif

// Adds this fragment's facing when it lies behind the span start; returns whether the
// fragment is inside the kept span (the ones a method stores). With the dynamic rules
// the object id is the frame class (core/trim/dynamic_frame_scene.h): u_winding counts
// the current frame, the dynamic state the reference frame and both frames' fragments
// behind the span start (the interval indices of the characterization bit vectors).
bool countWinding(ivec2 pixel, vec3 viewPos)
{
    bool kept = clipKeeps(viewPos);
    if (kept || behindSpanStart(viewPos)) {
        int behind = gl_FrontFacing ? -1 : 1;
#ifdef DYNAMIC_RULES
        if (objectInCurrentFrame(u_objectId))
            imageAtomicAdd(u_winding, pixel, behind);
        countDynamicBehind(pixel, u_objectId, behind);
#else
        imageAtomicAdd(u_winding, pixel, behind);
#endif
#ifdef OBJECT_WINDINGS
        if (u_objectId < uint(OBJECT_WINDINGS))
            atomicAdd(objectWindings[objectWindingBase(pixel) + u_objectId], behind);
#endif
    }
    return kept;
}
