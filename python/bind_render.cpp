#include "python/array_convert.h"
#include "python/bindings.h"
#include "python/python_errors.h"
#include "python/python_progress.h"
#include "python/scene_arguments.h"

#include "core/trim/reference_renderer.h"
#include "core/view/camera.h"
#include "render/gl/gl_error.h"
#include "render/gl/offscreen_gl_context.h"
#include "render/mfr/fragment_method.h"
#include "render/trim_renderer.h"

#include <QGuiApplication>
#include <QImage>

#include <cstdlib>
#include <memory>

namespace trimlab::python {

namespace {

// What one render produced, whichever backend made it.
struct RenderedImages {
    std::vector<std::uint8_t> rgb; ///< h × w × 3, row 0 at the top
    TrimImage trim;
};

Camera cameraFrom(const py::object& given, const Bounds& bounds, int width, int height)
{
    if (given.is_none())
        return fitCamera(bounds, double(width) / double(height));
    std::string text;
    if (py::isinstance<py::str>(given)) {
        text = given.cast<std::string>();
    } else {
        for (py::handle value : given)
            text +=
                (text.empty() ? "" : ",") + std::string(py::str(py::float_(py::reinterpret_borrow<py::object>(value))));
    }
    std::string error;
    const std::optional<Camera> camera = parseCamera(text, &error);
    if (!camera)
        throw InputError("camera: " + error);
    return withDepthRange(*camera, bounds);
}

RenderedImages renderReference(const Scene& scene, const Camera& camera, int width, int height,
                               const TrimSettings& settings, unsigned threads)
{
    const ReferenceRenderer reference(scene);
    ReferenceResult result = reference.render(camera, width, height, settings, threads);
    RenderedImages images;
    images.rgb.resize(std::size_t(width) * std::size_t(height) * 3);
    for (std::size_t i = 0; i < std::size_t(width) * std::size_t(height); ++i)
        for (std::size_t c = 0; c < 3; ++c)
            images.rgb[i * 3 + c] = result.color.rgba[i * 4 + c];
    images.trim = std::move(result.trim);
    return images;
}

// Qt needs an application object and, on X11, a display; without one it would abort the
// interpreter instead of failing, so the display is checked first.
void requireGuiApplication()
{
    if (QGuiApplication::instance())
        return;
    const bool display = std::getenv("DISPLAY") || std::getenv("WAYLAND_DISPLAY") || std::getenv("QT_QPA_PLATFORM");
    if (!display)
        throw RenderError("the OpenGL backend needs a display (run under xvfb-run -a, or use backend='reference')");
    static int argc = 1;
    static char name[] = "trimlab";
    static char* argv[] = {name, nullptr};
    new QGuiApplication(argc, argv); // lives as long as the process, as Qt expects
}

RenderedImages renderOpenGl(const Scene& scene, const Camera& camera, int width, int height,
                            const TrimSettings& settings, const std::string& method)
{
    const std::optional<render::FragmentMethodKind> kind = render::parseFragmentMethod(method);
    if (!kind)
        throw InputError("unknown method '" + method + "'");
    requireGuiApplication();
    try {
        render::OffscreenGlContext gl;
        render::TrimRenderer renderer(gl.context());
        renderer.setMethod(*kind);
        renderer.setScene(scene);
        renderer.render(camera, settings, width, height);
        const QImage color = renderer.readColor().convertToFormat(QImage::Format_RGB888);
        RenderedImages images;
        images.rgb.resize(std::size_t(width) * std::size_t(height) * 3);
        for (int y = 0; y < height; ++y)
            std::copy_n(color.constScanLine(y), std::size_t(width) * 3, images.rgb.data() + std::size_t(y) * width * 3);
        images.trim = renderer.readTrimImage();
        return images;
    } catch (const render::GlUnavailableError& e) {
        throw RenderError(e.what());
    }
}

py::dict imagesDict(RenderedImages&& images, int width, int height)
{
    const py::ssize_t h = height, w = width;
    std::uint8_t* rgb = nullptr;
    py::capsule owner = ownerOf(std::move(images.rgb), rgb);
    py::array_t<std::uint8_t> color({h, w, py::ssize_t(3)}, {w * 3, py::ssize_t(3), py::ssize_t(1)}, rgb, owner);
    py::array_t<float> depth({h, w});
    py::array_t<std::int32_t> ids({h, w});
    py::array_t<std::int32_t> objects({h, w});
    auto d = depth.mutable_unchecked<2>();
    auto p = ids.mutable_unchecked<2>();
    auto o = objects.mutable_unchecked<2>();
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const TrimPixel& pixel = images.trim.at(x, y);
            d(y, x) = pixel.viewDepth;
            p(y, x) = pixel.primitiveId;
            o(y, x) = pixel.objectId;
        }
    }
    py::dict result;
    result["color"] = color;
    result["depth"] = depth;
    result["ids"] = ids;
    result["objects"] = objects;
    return result;
}

py::dict renderImages(const py::object& meshes, const py::object& triangles, int width, int height,
                      const std::string& rule, const py::object& csg, const py::object& rules, bool trim,
                      const py::object& camera, const std::string& backend, const std::string& method, unsigned threads)
{
    if (width < 1 || height < 1 || width > 16384 || height > 16384)
        throw InputError("width and height must be 1 to 16384, got " + std::to_string(width) + "x" +
                         std::to_string(height));
    if (backend != "reference" && backend != "opengl")
        throw InputError("unknown backend '" + backend + "' (use reference or opengl)");
    const LoadedScene loaded = sceneFromArguments(meshes, triangles);
    TrimSettings settings = trimSettingsFromArguments(rule, csg, rules, loaded.scene.objects.size());
    settings.trimEnabled = trim;
    if (trim)
        requireTrimmable(loaded);
    const Camera view = cameraFrom(camera, loaded.scene.worldBounds(), width, height);
    RenderedImages images;
    if (backend == "reference") {
        py::gil_scoped_release release;
        images = renderReference(loaded.scene, view, width, height, settings, threads);
    } else {
        images = renderOpenGl(loaded.scene, view, width, height, settings, method);
    }
    return imagesDict(std::move(images), width, height);
}

constexpr const char* kRenderDoc =
    R"doc(render(V, F, *, width=640, height=480, rule="alternating-border", csg=None, rules=None, trim=True, camera=None, backend="reference", method="kplus-array", threads=0) -> dict
render([(V0, F0), ...], ...) -> dict

An image of the trimmed surface as `trimlab render` makes it: each pixel shows the first
surface point whose two sides classify differently under the rule (or the CSG
expression; trim=False: the plain first surface). backend "reference" is the exact CPU
ray caster (always available, the GIL released); "opengl" runs the multi-fragment
`method` (kplus-array, kplus-heap, s-buffer, kplus-sbuffer, abuffer-fixed,
abuffer-linked-list, peeling-f2b, peeling-dual, two-pass) on an
OpenGL 4.3 context (needs a display: xvfb-run -a) and raises RenderError without one.
camera: None fits the view to the bounds; else "ex,ey,ez,tx,ty,tz,ux,uy,uz,fovy" or a
sequence of those 10 numbers (eye, target, up, vertical field of view in degrees).

Returns {"color": (h, w, 3) uint8, "depth": (h, w) float32 view depth (inf where
empty), "ids": (h, w) int32 triangle index (-1 empty), "objects": (h, w) int32 object
id}. Raises InputError, NotTrimmableError (trim=True on an open mesh), RenderError.)doc";

} // namespace

void bindRender(py::module_& m)
{
    m.def("render", &renderImages, py::arg("meshes"), py::arg("F") = py::none(), py::kw_only(), py::arg("width") = 640,
          py::arg("height") = 480, py::arg("rule") = "alternating-border", py::arg("csg") = py::none(),
          py::arg("rules") = py::none(), py::arg("trim") = true, py::arg("camera") = py::none(),
          py::arg("backend") = "reference", py::arg("method") = "kplus-array", py::arg("threads") = 0u, kRenderDoc);
}

} // namespace trimlab::python
