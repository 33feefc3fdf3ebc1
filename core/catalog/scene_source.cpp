#include "core/catalog/scene_source.h"

#include "core/mesh/mesh_io.h"
#include "core/mesh/mesh_load_error.h"
#include "core/catalog/demo_scenes.h"
#include "core/surface/nurbs_json.h"
#include "core/catalog/surface_scenes.h"
#include "core/timeline/frame_chain.h"
#include "core/timeline/project_file.h"

#include <cctype>
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

bool isProjectFileName(const std::string& path)
{
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    return extension == ".trimlab";
}

// A project as a scene: a scene project's objects and settings, or a history's last frame.
LoadedScene projectFileScene(const std::string& path, const std::string& displayName)
{
    timeline::Project project;
    try {
        project = timeline::readProject(path);
    } catch (const timeline::ProjectFileError& error) {
        // One error type for every file a scene is read from (the callers catch it).
        throw MeshLoadError(error.file(), error.reason(), MeshErrorLocation{0, error.where()});
    }
    if (project.scene)
        return projectSceneLoaded(*project.scene, project.extras.staticRule, path, displayName);
    LoadedScene loaded;
    loaded.source = path;
    loaded.displayName = displayName;
    loaded.scene =
        timeline::frameScene(project.timeline, project.timeline.frameCount() - 1, glm::dmat4(1.0), displayName);
    loaded.savedRule = project.extras.staticRule;
    for (const SceneObject& object : loaded.scene.objects)
        loaded.reports.push_back(validateMesh(object.mesh));
    return loaded;
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
            return (reports.size() > 1 ? "Object '" + name + "': " : std::string()) +
                   reports[i].trimUnavailableReason();
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
    } else if (isProjectFileName(source)) {
        return projectFileScene(source, std::filesystem::path(source).filename().string());
    } else {
        loaded.displayName = std::filesystem::path(source).filename().string();
        loaded.scene = fileScene(source);
    }
    for (const SceneObject& object : loaded.scene.objects)
        loaded.reports.push_back(validateMesh(object.mesh));
    return loaded;
}

LoadedScene projectSceneLoaded(const timeline::ProjectScene& scene, const std::optional<StaticRule>& rule,
                               const std::string& source, const std::string& displayName)
{
    LoadedScene loaded;
    loaded.source = source;
    loaded.displayName = displayName;
    loaded.scene.objects = scene.objects;
    for (const SceneObject& object : loaded.scene.objects)
        loaded.reports.push_back(validateMesh(object.mesh));
    loaded.savedCsg = scene.csg;
    loaded.savedRule = rule;
    return loaded;
}

timeline::ProjectScene projectSceneOf(const LoadedScene& loaded, const CsgSettings& csg)
{
    return timeline::ProjectScene{loaded.scene.objects, csg};
}

LoadedScene loadScenes(const std::vector<std::string>& sources)
{
    if (sources.empty())
        throw std::invalid_argument("No scene source given.");
    LoadedScene all = loadScene(sources.front());
    for (std::size_t i = 1; i < sources.size(); ++i) {
        LoadedScene next = loadScene(sources[i]);
        const std::size_t total = all.scene.objects.size() + next.scene.objects.size();
        if (total > Scene::maxObjects)
            throw std::invalid_argument("Too many objects: the sources up to " + sources[i] + " hold " +
                                        std::to_string(total) + ", a scene holds at most " +
                                        std::to_string(Scene::maxObjects) + ".");
        all.displayName += " + " + next.displayName;
        all.savedCsg = {};
        all.savedRule.reset();
        for (SceneObject& object : next.scene.objects)
            all.scene.objects.push_back(std::move(object));
        for (MeshValidationReport& report : next.reports)
            all.reports.push_back(std::move(report));
    }
    return all;
}

} // namespace trimlab
