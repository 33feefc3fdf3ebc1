#include "core/catalog/scene_source.h"

#include "core/mesh/mesh_io.h"
#include "core/mesh/mesh_load_error.h"
#include "core/catalog/demo_scenes.h"
#include "core/surface/nurbs_json.h"
#include "core/catalog/surface_scenes.h"

#include <filesystem>
#include <stdexcept>

namespace trimlab {

namespace {

Scene demoScene(std::string_view name)
{
    if (std::optional<Scene> scene = makeDemoScene(name))
        return std::move(*scene);
    if (std::optional<Scene> scene = makeSurfaceDemoScene(name))
        return std::move(*scene);
    std::string known;
    for (const DemoEntry& demo : builtInDemos())
        known += (known.empty() ? "" : ", ") + demo.source;
    throw std::invalid_argument("Unknown demo scene '" + std::string(name) + "'. Known demos: " + known + ".");
}

Scene fileScene(const std::string& path)
{
    if (isNurbsFileName(path)) {
        try {
            return nurbsFileScene(path);
        } catch (const NurbsFileError& error) {
            // One error type for every file a scene is read from (the callers catch it).
            throw MeshLoadError(error.file(), error.reason(), MeshErrorLocation{0, error.where()});
        } catch (const std::invalid_argument& error) {
            throw MeshLoadError(path, error.what());
        }
    }
    Scene scene;
    scene.objects.push_back({std::filesystem::path(path).filename().string(), loadMesh(path), glm::dmat4(1.0)});
    return scene;
}

} // namespace

std::vector<DemoEntry> builtInDemos()
{
    std::vector<DemoEntry> demos;
    for (const std::string& name : demoSceneNames())
        demos.push_back({std::string(kDemoPrefix) + name, demoSceneDescription(name)});
    for (const std::string& name : surfaceDemoNames())
        demos.push_back({std::string(kDemoPrefix) + name, surfaceDemoDescription(name)});
    return demos;
}

bool isDemoSource(std::string_view source)
{
    return source.substr(0, kDemoPrefix.size()) == kDemoPrefix;
}

bool LoadedScene::trimmable() const
{
    for (const MeshValidationReport& report : reports)
        if (!report.trimmable())
            return false;
    return true;
}

std::string LoadedScene::trimUnavailableReason() const
{
    for (std::size_t i = 0; i < reports.size(); ++i) {
        if (!reports[i].trimmable()) {
            const std::string& name = scene.objects[i].name;
            return (reports.size() > 1 ? "Object '" + name + "': " : std::string()) + reports[i].trimUnavailableReason();
        }
    }
    return {};
}

LoadedScene loadScene(const std::string& source)
{
    LoadedScene loaded;
    loaded.source = source;
    if (isDemoSource(source)) {
        loaded.displayName = source.substr(kDemoPrefix.size());
        loaded.scene = demoScene(loaded.displayName);
    } else {
        loaded.displayName = std::filesystem::path(source).filename().string();
        loaded.scene = fileScene(source);
    }
    for (const SceneObject& object : loaded.scene.objects)
        loaded.reports.push_back(validateMesh(object.mesh));
    return loaded;
}

} // namespace trimlab
