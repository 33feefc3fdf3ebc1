// Outputs of every trim resolve: the shaded color and an id texel that tests, picking
// and the --ids/--depth exports read back (render/frame/render_target.h decodes it):
//   x: primitive id + 1 (0 = empty pixel)
//   y: object id (bits 0-7) | front-facing (bit 8) | back-facing (bit 9)
//      | overflowed (bit 10) | unresolved (bit 11) | collision (bit 12)
//      | cap plane + 1 (bits 13-15, 0 = no cap) | coplanar count (bits 16-23)
//   z: view depth (float bits; +inf for empty pixels)
//   w: winding index at the start of the kept span (int bits)
// Needs fragment_pack.glsl, frame_counters.glsl, trim_walk.glsl, trim_shading.glsl and
// scene_data.glsl.

layout(location = 0) out vec4 o_color;
layout(location = 1) out uvec4 o_info;

const uint INFO_FRONT_FACING = 1u << 8;
const uint INFO_BACK_FACING = 1u << 9;
const uint INFO_OVERFLOWED = 1u << 10;
const uint INFO_UNRESOLVED = 1u << 11;
const uint INFO_COLLISION = 1u << 12;
const uint INFO_CAP_SHIFT = 13u;
const uint INFO_COPLANAR_SHIFT = 16u;
const vec3 COLLISION_COLOR = vec3(0.95, 0.10, 0.08); // core/trim/trim_shading.h
const float COLLISION_TINT = 0.65;
const uint FLOAT_BITS_INFINITY = 0x7F800000u;

uniform mat4 u_projection;
uniform uint u_carvedObjects; // csgSubtractedMask of the CSG (0 without one)
uniform vec2 u_viewportSize;
uniform vec2 u_tanHalfFov; // (tan(fovx/2), tan(fovy/2))

// View-space direction of this pixel's ray, scaled to z = -1 (so point = dir * depth).
vec3 pixelRayDirection()
{
    vec2 ndc = gl_FragCoord.xy / u_viewportSize * 2.0 - 1.0;
    return vec3(ndc * u_tanHalfFov, -1.0);
}

// Window-space depth of a view-space point, so later passes can depth-test against it.
float windowDepth(vec3 viewPos)
{
    vec4 clip = u_projection * vec4(viewPos, 1.0);
    return clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0);
}

// A pixel showing nothing. `unresolved`: fragments were lost and the trim point may be
// among them, so the pixel is painted UNRESOLVED_COLOR rather than shown wrong.
void emitEmptyPixel(int windingAtStart, bool overflowed, bool unresolved)
{
    uint flags = (overflowed ? INFO_OVERFLOWED : 0u) | (unresolved ? INFO_UNRESOLVED : 0u);
    o_color = vec4(unresolved ? UNRESOLVED_COLOR : BACKGROUND_COLOR, 1.0);
    o_info = uvec4(0u, flags, FLOAT_BITS_INFINITY, uint(windingAtStart));
    gl_FragDepth = 1.0;
}

// Coplanar group colors of thesis Fig. 6.9 (core/trim/trim_shading.h, coplanarColor).
vec3 coplanarColor(int count)
{
    const vec3 palette[8] = vec3[8](vec3(0.90, 0.10, 0.10), vec3(0.15, 0.30, 0.95), vec3(0.10, 0.80, 0.20),
                                    vec3(0.10, 0.90, 0.90), vec3(0.50, 1.00, 0.83), vec3(1.00, 0.00, 1.00),
                                    vec3(1.00, 0.95, 0.10), vec3(0.60, 0.35, 0.15));
    return palette[clamp(count, 2, 9) - 2];
}

// The highlights of the shown fragment (applyHighlights in trim_shading.h), counted.
vec3 applyHighlights(vec3 shaded, float lighting, bool collision, int coplanar)
{
    vec3 color = shaded;
    if (coplanar >= 2) {
        color = coplanarColor(coplanar) * lighting;
        atomicCounterIncrement(u_coplanarPixels);
    }
    if (collision) {
        color = color + (COLLISION_COLOR * lighting - color) * COLLISION_TINT;
        atomicCounterIncrement(u_collisionPixels);
    }
    return color;
}

// A pixel showing the stored fragment `f`, shaded with the trim palette (or the scene's
// vertex colors when u_vertexColors, darkened on the back side), with the highlights the
// walk found for it (trim_walk.glsl: shownCollision, shownCoplanarCount).
void emitShownPixel(uvec2 f, int windingAtStart, bool overflowed)
{
    bool front = fragmentFrontFacing(f);
    vec3 viewPos = pixelRayDirection() * fragmentDepth(f);
    SurfacePoint surface = surfacePoint(fragmentObject(f), fragmentPrimitive(f), viewPos);
    vec3 normal = interpolatedViewNormal(surface);
    vec3 toViewer = normalize(-viewPos);
    bool carved = !front && ((u_carvedObjects >> fragmentObject(f)) & 1u) != 0u;
    vec3 shaded = u_vertexColors ? shadeColoredPoint(interpolatedColor(surface), front, normal, toViewer)
                  : carved       ? shadeCarvedWall(normal, toViewer)
                                 : shadeTrimPoint(front, normal, toViewer);
    bool collision = shownCollision();
    int coplanar = min(shownCoplanarCount(), 255);
    float lighting = AMBIENT + (1.0 - AMBIENT) * abs(dot(normal, toViewer));
    o_color = vec4(applyHighlights(shaded, lighting, collision, coplanar), 1.0);
    uint flags = fragmentObject(f) | (front ? INFO_FRONT_FACING : INFO_BACK_FACING) | (overflowed ? INFO_OVERFLOWED : 0u) |
                 (collision ? INFO_COLLISION : 0u) | (uint(coplanar) << INFO_COPLANAR_SHIFT);
    o_info = uvec4(fragmentPrimitive(f) + 1u, flags, f.x, uint(windingAtStart));
    gl_FragDepth = windowDepth(viewPos);
}
