#pragma once
/// \file
/// Depth images of CSG products rendered by OpenCSG (Kirsch & Döllner's image-based
/// Goldfeather / SCS algorithms): an implementation independent of TrimLab's, for the
/// render test that guards against the CPU reference and the GPU methods sharing a
/// mistake. Kept in its own translation unit because it needs GLEW's headers, which do
/// not mix with Qt's OpenGL headers.

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace trimlab::test {

/// One solid: world-space triangles (#T×3 corners, counter-clockwise seen from outside)
/// and the most front faces a ray can cross (OpenCSG's convexity; 1 for convex solids).
struct OpenCsgSolid {
    std::vector<glm::dvec3> corners;
    unsigned convexity = 1;
};

/// A CSG product: the intersection of `intersected` minus every `subtracted` solid
/// (indices into the solid list). A union is a list of products.
struct OpenCsgProduct {
    std::vector<int> intersected;
    std::vector<int> subtracted;
};

/// Renders each product with OpenCSG into an offscreen framebuffer of width×height with
/// the given view and projection (OpenGL conventions) and returns, row 0 at the top, the
/// window depth of the union of the products (the smallest over the products; 1 where
/// none covers the pixel). Needs a current OpenGL compatibility context (OpenCSG uses the
/// fixed-function pipeline); initializes GLEW on it. Returns an empty vector and sets
/// `error` when GLEW or the framebuffer cannot be set up.
[[nodiscard]] std::vector<float> renderOpenCsgDepth(const std::vector<OpenCsgSolid>& solids,
                                                    const std::vector<OpenCsgProduct>& products, const glm::dmat4& view,
                                                    const glm::dmat4& projection, int width, int height,
                                                    std::string* error);

} // namespace trimlab::test
