// Outputs of every trim resolve: the shaded color and an id texel that tests, picking
// and the --ids/--depth exports read back (render/render_target.h decodes it):
//   x: primitive id + 1 (0 = empty pixel)
//   y: object id (bits 0-7) | front-facing (bit 8) | back-facing (bit 9)
//      | overflowed (bit 10) | unresolved (bit 11)
//   z: view depth (float bits; +inf for empty pixels)
//   w: winding index at the start of the kept span (int bits)
// Needs fragment_pack.glsl, trim_shading.glsl and scene_data.glsl.

layout(location = 0) out vec4 o_color;
layout(location = 1) out uvec4 o_info;

const uint INFO_FRONT_FACING = 1u << 8;
const uint INFO_BACK_FACING = 1u << 9;
const uint INFO_OVERFLOWED = 1u << 10;
const uint INFO_UNRESOLVED = 1u << 11;
const uint FLOAT_BITS_INFINITY = 0x7F800000u;

uniform mat4 u_projection;
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

// A pixel showing the stored fragment `f`, shaded with the trim palette (or the scene's
// vertex colors when u_vertexColors, darkened on the back side).
void emitShownPixel(uvec2 f, int windingAtStart, bool overflowed)
{
    bool front = fragmentFrontFacing(f);
    vec3 viewPos = pixelRayDirection() * fragmentDepth(f);
    SurfacePoint surface = surfacePoint(fragmentObject(f), fragmentPrimitive(f), viewPos);
    vec3 normal = interpolatedViewNormal(surface);
    vec3 toViewer = normalize(-viewPos);
    o_color = vec4(u_vertexColors ? shadeColoredPoint(interpolatedColor(surface), front, normal, toViewer)
                                  : shadeTrimPoint(front, normal, toViewer),
                   1.0);
    uint flags = fragmentObject(f) | (front ? INFO_FRONT_FACING : INFO_BACK_FACING) | (overflowed ? INFO_OVERFLOWED : 0u);
    o_info = uvec4(fragmentPrimitive(f) + 1u, flags, f.x, uint(windingAtStart));
    gl_FragDepth = windowDepth(viewPos);
}
