// A trim walk kept in an IMAGE_WALK layer between peeling passes, plus the per-pixel
// values the walk and resolve passes of F2B and DUAL read (peel_state.glsl).
//   x: winding index (int bits)  y: WALK_* flags  zw: shown fragment (fragment_pack.glsl)
// Needs fragment_pack.glsl, static_rule.glsl, trim_walk.glsl, peel_state.glsl.

layout(binding = IMAGE_WINDING, r32i) uniform readonly iimage2D u_winding;
layout(binding = IMAGE_COUNTER, r32ui) uniform coherent uimage2D u_counter; // fragments peeled

struct PeelWalk {
    TrimWalk walk;
    bool done;
    bool inconsistent;
};

PeelWalk loadPeelWalk(ivec2 pixel, int layer)
{
    uvec4 v = imageLoad(u_walk, ivec3(pixel, layer));
    TrimWalk walk = TrimWalk(int(v.x), (v.y & WALK_FOUND) != 0u, v.zw);
    return PeelWalk(walk, (v.y & WALK_DONE) != 0u, (v.y & WALK_INCONSISTENT) != 0u);
}

void storePeelWalk(ivec2 pixel, int layer, PeelWalk p)
{
    uint flags = (p.done ? WALK_DONE : 0u) | (p.walk.found ? WALK_FOUND : 0u) |
                 (p.inconsistent ? WALK_INCONSISTENT : 0u);
    imageStore(u_walk, ivec3(pixel, layer), uvec4(uint(p.walk.winding), flags, p.walk.shown));
}

int windingAtStart(ivec2 pixel) { return imageLoad(u_winding, pixel).r; }
uint peeledCount(ivec2 pixel) { return imageLoad(u_counter, pixel).r; }
uint spanCount(ivec2 pixel) { return peelLoad(pixel, PEEL_SPAN_COUNT); }
