// Per-pixel, per-object winding indices at the start of the kept span (core/trim/
// trim_walk.h, "Per-object windings"; render/passes/object_windings.h owns the buffer):
// OBJECT_WINDINGS ints per pixel for the objects 0 .. OBJECT_WINDINGS - 1, counted from
// the far side in the same geometry pass as the summed index (winding_count.glsl) and read
// by the resolve to start the walk. The includer defines OBJECT_WINDINGS_ACCESS.

// The row length is a uniform, not a header in the buffer: on NVIDIA's driver a header
// written with glBufferSubData right after the buffer's glClearBufferData was not seen by
// the first frame after allocation (every row read width 0: vertical stripes).
uniform uint u_objectWindingWidth; // pixels per row

layout(std430, binding = STORAGE_OBJECT_WINDINGS) OBJECT_WINDINGS_ACCESS buffer ObjectWindingCounts {
    int objectWindings[];
};

uint objectWindingBase(ivec2 pixel)
{
    return (uint(pixel.y) * u_objectWindingWidth + uint(pixel.x)) * uint(OBJECT_WINDINGS);
}
