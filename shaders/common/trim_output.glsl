// Outputs of every trim resolve pass: the shaded color and an id texel that tests,
// picking and the --ids/--depth exports read back (render/render_target.h decodes it):
//   x: primitive id + 1 (0 = empty pixel)
//   y: object id (bits 0-7) | front-facing (bit 8) | back-facing (bit 9)
//      | overflowed (bit 10) | unresolved (bit 11)
//   z: view depth (float bits; +inf for empty pixels)
//   w: winding index at the start of the kept span (int bits)

layout(location = 0) out vec4 o_color;
layout(location = 1) out uvec4 o_info;

const uint INFO_FRONT_FACING = 1u << 8;
const uint INFO_BACK_FACING = 1u << 9;
const uint INFO_OVERFLOWED = 1u << 10;
const uint INFO_UNRESOLVED = 1u << 11;

uniform mat4 u_projection;

// Window-space depth of a view-space point, so later passes can depth-test against it.
float windowDepth(vec3 viewPos)
{
    vec4 clip = u_projection * vec4(viewPos, 1.0);
    return clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0);
}
