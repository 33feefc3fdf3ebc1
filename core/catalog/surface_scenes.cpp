#include "core/catalog/surface_scenes.h"

#include "core/surface/editable_surface.h"
#include "core/catalog/fig8_13_history.h"
#include "core/catalog/scene_source.h"
#include "core/surface/nurbs_json.h"
#include "core/surface/nurbs_primitives.h"
#include "core/surface/subdivision_cages.h"
#include "core/timeline/control_edit.h"
#include "core/mesh/mesh_load_error.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <exception>
#include <optional>

namespace trimlab {

namespace {

struct SurfaceDemo {
    std::string_view name;
    std::string_view description;
};

constexpr std::array<SurfaceDemo, 6> kSurfaceDemos{{
    {"nurbs-sphere", "NURBS unit sphere (9x5 rational net, degree 2), tessellated"},
    {"nurbs-torus", "NURBS torus (9x9 rational net, degree 2), tessellated"},
    {"nurbs-fig8-13", "NURBS sphere whose north pole was pushed through the south side (thesis Fig. 8.13)"},
    {"subdivision-cube", "Catmull-Clark cube cage, level 3, limit surface"},
    {"subdivision-torus", "Catmull-Clark torus cage (16x8), level 2, limit surface"},
    {"subdivision-push", "Catmull-Clark cube whose cage corner was pushed through the body"},
}};

bool endsWithNoCase(std::string_view text, std::string_view suffix)
{
    if (text.size() < suffix.size())
        return false;
    return std::equal(suffix.begin(), suffix.end(), text.end() - std::ptrdiff_t(suffix.size()), [](char a, char b) {
        return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
    });
}

Scene oneObject(std::string name, TriangleMesh mesh)
{
    Scene scene;
    scene.objects.push_back({std::move(name), std::move(mesh), glm::dmat4(1.0)});
    return scene;
}

} // namespace

bool isNurbsFileName(std::string_view path)
{
    return endsWithNoCase(path, ".nurbs.json") || endsWithNoCase(path, ".nurbs");
}

Scene nurbsFileScene(const std::string& path)
{
    const std::vector<NurbsSurface> surfaces = loadNurbsJson(path);
    Scene scene;
    for (std::size_t s = 0; s < surfaces.size(); ++s) {
        std::optional<EditableSurface> tessellated;
        try {
            tessellated.emplace(nurbsDefinition(surfaces[s]));
        } catch (const std::invalid_argument& error) {
            throw MeshLoadError(path, error.what(), MeshErrorLocation{0, "surfaces[" + std::to_string(s) + "]"});
        }
        const EditableSurface& surface = *tessellated;
        const std::string name = surfaces[s].name.empty() ? "surface " + std::to_string(s) : surfaces[s].name;
        scene.objects.push_back({name, surface.mesh(), glm::dmat4(1.0)});
    }
    return scene;
}

std::vector<std::string> surfaceDemoNames()
{
    std::vector<std::string> names;
    for (const SurfaceDemo& demo : kSurfaceDemos)
        names.emplace_back(demo.name);
    return names;
}

std::string_view surfaceDemoDescription(std::string_view name)
{
    for (const SurfaceDemo& demo : kSurfaceDemos)
        if (demo.name == name)
            return demo.description;
    return {};
}

std::optional<SurfaceDefinition> surfaceDemoDefinition(std::string_view name)
{
    if (name == "nurbs-sphere")
        return nurbsDefinition(makeNurbsSphere(glm::dvec3(0.0), 1.0));
    if (name == "nurbs-torus")
        return nurbsDefinition(makeNurbsTorus(glm::dvec3(0.0), 1.0, 0.4), 48, 24);
    if (name == "subdivision-cube")
        return subdivisionDefinition(cubeCage(0.8), SubdivisionSettings{3, SubdivisionMode::Limit});
    if (name == "subdivision-torus")
        return subdivisionDefinition(torusCage(), SubdivisionSettings{2, SubdivisionMode::Limit});
    return std::nullopt;
}

bool hasSurfaceDemoHistory(std::string_view name)
{
    return name == "nurbs-fig8-13" || name == "subdivision-push";
}

std::optional<timeline::Timeline> surfaceDemoHistory(std::string_view name)
{
    if (name == "nurbs-fig8-13")
        return fig8_13NurbsHistory();
    if (name == "subdivision-push")
        return subdivisionPushHistory();
    return std::nullopt;
}

std::optional<Scene> makeSurfaceDemoScene(std::string_view name)
{
    if (const std::optional<timeline::Timeline> history = surfaceDemoHistory(name))
        return oneObject(std::string(name), history->meshAt(history->frameCount() - 1));
    const std::optional<SurfaceDefinition> definition = surfaceDemoDefinition(name);
    if (!definition)
        return std::nullopt;
    return oneObject(std::string(name), EditableSurface(*definition).mesh());
}

std::optional<timeline::Timeline> surfaceDemoHistory(std::string_view source, const TriangleMesh& shown)
{
    if (!isDemoSource(source))
        return std::nullopt;
    const std::optional<SurfaceDefinition> definition = surfaceDemoDefinition(source.substr(kDemoPrefix.size()));
    if (!definition)
        return std::nullopt;
    try {
        timeline::Timeline history = surfaceTimeline(*definition);
        if (history.base().triangles != shown.triangles || history.base().positions != shown.positions)
            return std::nullopt;
        return history;
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

} // namespace trimlab
