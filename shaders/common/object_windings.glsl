// Per-pixel, per-object winding indices at the start of the kept span (core/trim/
// trim_walk.h, "Per-object windings"; render/passes/object_windings.h owns the buffer):
// OBJECT_WINDINGS ints per pixel for the objects 0 .. OBJECT_WINDINGS - 1, counted from
// the far side in the same geometry pass as the summed index (winding_count.glsl) and read
// by the resolve to start the walk. The includer defines OBJECT_WINDINGS_ACCESS.

layout(std430, binding = STORAGE_OBJECT_WINDINGS) OBJECT_WINDINGS_ACCESS buffer ObjectWindingCounts {
    uint objectWindingWidth; // pixels per row
    uint objectWindingPad;
    int objectWindings[];
};

uint objectWindingBase(ivec2 pixel)
{
    return (uint(pixel.y) * objectWindingWidth + uint(pixel.x)) * uint(OBJECT_WINDINGS);
}
