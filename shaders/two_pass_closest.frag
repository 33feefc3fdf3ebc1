#version 430 core
// Second geometry pass of the two-pass method (thesis Algorithm 8.10, ClosestRender):
// the nearest fragment of each pixel's kept span, by the hardware depth test (LESS, into
// the method's own 32-bit float depth buffer), written as a packed fragment.
// The test decides exactly in the walk order of the CPU reference (view depth, then
// object id, then primitive id): the depth written is the view depth times a power of
// two, which is exact in float and keeps every distinction of the view depth; at equal
// depth, LESS keeps the fragment that came first, and OpenGL applies per-fragment
// operations in primitive order, which GpuScene::draw makes object by object and, within
// an object, by primitive id.

#include "common/fragment_pack.glsl"
#include "common/clip.glsl"

uniform uint u_objectId;
uniform float u_depthScale; // a power of two with zFar * u_depthScale < 1

in vec3 v_viewPos;

layout(location = 0) out uvec2 o_fragment;

void main()
{
    if (!clipKeeps(v_viewPos))
        discard;
    float depth = -v_viewPos.z;
    gl_FragDepth = depth * u_depthScale;
    o_fragment = packFragment(depth, uint(gl_PrimitiveID), u_objectId, gl_FrontFacing);
}
