#pragma once
/// \file
/// Depth images of CSG products rendered by OpenCSG (Kirsch & Döllner's image-based
/// Goldfeather / SCS algorithms): an implementation independent of TrimLab's, for the
/// render test that guards against the CPU reference and the GPU methods sharing a
/// mistake, and the peer that bench_opencsg times beside TrimLab's methods. Kept in its own translation unit because it needs GLEW's headers, which do
/// not mix with Qt's OpenGL headers.

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <memory>
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

/// The view depth of window depth `d` (< 1) under a perspective projection with planes
/// `zNear`, `zFar` (OpenGL conventions).
[[nodiscard]] inline double openCsgViewDepth(double d, double zNear, double zFar)
{
    const double z = 2.0 * d - 1.0;
    return 2.0 * zFar * zNear / (zFar + zNear - z * (zFar - zNear));
}

/// OpenCSG's algorithm: Goldfeather takes any closed solid (concave ones by their
/// convexity), SCS only convex ones; Automatic lets OpenCSG choose per product.
enum class OpenCsgAlgorithm { Goldfeather, Scs, Automatic };

/// OpenCSG set up once for repeated frames of the same solids and products at one size,
/// as a viewer draws them: each solid in a vertex buffer, the framebuffer kept. Needs the
/// same current OpenGL compatibility context from construction to destruction; initializes
/// GLEW on it.
class OpenCsgRenderer {
public:
    OpenCsgRenderer(const std::vector<OpenCsgSolid>& solids, std::vector<OpenCsgProduct> products, int width,
                    int height, OpenCsgAlgorithm algorithm = OpenCsgAlgorithm::Goldfeather);
    ~OpenCsgRenderer();
    OpenCsgRenderer(const OpenCsgRenderer&) = delete;
    OpenCsgRenderer& operator=(const OpenCsgRenderer&) = delete;

    /// Empty when the renderer is ready; else why not (GLEW, the framebuffer).
    [[nodiscard]] const std::string& error() const { return m_error; }
    /// Renders every product with the view and projection (OpenGL conventions). Returns
    /// the frame's GPU time in milliseconds (GL_TIME_ELAPSED over OpenCSG's passes, the
    /// depth readback of each product excluded; negative without a timer query).
    double render(const glm::dmat4& view, const glm::dmat4& projection);
    /// The window depth of the last render's union, row 0 at the top (the smallest over
    /// the products; 1 where none covers the pixel).
    [[nodiscard]] const std::vector<float>& depth() const { return m_depth; }

private:
    struct Gl;
    std::string m_error;
    std::vector<OpenCsgProduct> m_products;
    int m_width = 0;
    int m_height = 0;
    OpenCsgAlgorithm m_algorithm;
    std::vector<float> m_depth;
    std::unique_ptr<Gl> m_gl;
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
