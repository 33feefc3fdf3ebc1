// The clipping plane in view space, and which fragments count toward the winding index
// at the start of a pixel's kept span (core/trim/clip_plane.h explains the span).

uniform bool u_clipEnabled;
uniform vec4 u_clipPlaneView; // (n, d) in view space; kept where dot(n, p) + d >= 0
uniform float u_zNear;

// `precise`: a count pass and a later store pass must classify every fragment alike.
bool clipKeeps(vec3 viewPos)
{
    precise float side = dot(u_clipPlaneView.xyz, viewPos) + u_clipPlaneView.w;
    return !u_clipEnabled || side >= 0.0;
}

// True when the pixel ray through `viewPos` starts (at the near plane) on the kept side.
// Then every fragment lies behind the span start; otherwise only the kept ones do.
bool rayStartsAtNear(vec3 viewPos)
{
    return clipKeeps(viewPos * (u_zNear / -viewPos.z));
}
