#version 430 core
// Geometry passes: positions to clip space and the view-space position to fragments.

layout(location = 0) in vec3 a_position;

uniform mat4 u_modelView;
uniform mat4 u_projection;

out vec3 v_viewPos;
// Methods that count fragments in one geometry pass and store them in another (S-buffer,
// K+B-SB) need both passes to rasterise exactly the same fragments.
invariant gl_Position;
invariant v_viewPos;

void main()
{
    vec4 viewPos = u_modelView * vec4(a_position, 1.0);
    v_viewPos = viewPos.xyz;
    gl_Position = u_projection * viewPos;
}
