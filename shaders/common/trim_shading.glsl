// How a shown trim point is colored. The C++ twin is core/trim/trim_shading.h; keep the
// constants identical (render tests compare GPU colors with the CPU reference).

const vec3 FRONT_FACING_COLOR = vec3(0.96, 0.78, 0.26);
const vec3 BACK_FACING_COLOR = vec3(0.28, 0.50, 0.96);
const vec3 BACKGROUND_COLOR = vec3(0.16, 0.17, 0.20);
const vec3 CARVED_WALL_COLOR = vec3(0.24, 0.70, 0.62); // the back face of a subtracted CSG operand
const vec3 UNRESOLVED_COLOR = vec3(1.0, 0.0, 1.0); // overflowed pixel whose trim lies beyond k
const float AMBIENT = 0.25;

vec3 shadeTrimPoint(bool frontFacing, vec3 normal, vec3 toViewer)
{
    vec3 base = frontFacing ? FRONT_FACING_COLOR : BACK_FACING_COLOR;
    return base * (AMBIENT + (1.0 - AMBIENT) * abs(dot(normal, toViewer)));
}

// A back face of an object the CSG subtracts: the wall the difference carved.
vec3 shadeCarvedWall(vec3 normal, vec3 toViewer)
{
    return CARVED_WALL_COLOR * (AMBIENT + (1.0 - AMBIENT) * abs(dot(normal, toViewer)));
}

// Shading with a per-vertex color (e.g. a segmentation): the back side, seen through a
// cut or a trimmed hole, is darkened so inside and outside stay distinguishable.
vec3 shadeColoredPoint(vec3 color, bool frontFacing, vec3 normal, vec3 toViewer)
{
    vec3 base = frontFacing ? color : 0.55 * color;
    return base * (AMBIENT + (1.0 - AMBIENT) * abs(dot(normal, toViewer)));
}
