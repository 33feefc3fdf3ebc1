#include "ui/common/loaded_animation.h"

#include "core/animation/animation_loader.h"
#include "core/animation/closed_animation.h"
#include "core/catalog/pose_scene.h"
#include "core/skinning/file_skin_model.h"

#include <chrono>
#include <filesystem>

namespace trimlab::ui {

namespace {

/// "walking-cat" for "anim/walking-cat/", "mesh_*.obj" for a pattern, the file name of a glTF.
std::string displayNameOf(const std::string& source)
{
    std::filesystem::path path(source);
    if (!path.has_filename())
        path = path.parent_path();
    const std::string name = path.filename().string();
    return name.empty() ? source : name;
}

Bounds poseBounds(const MeshAnimation& animation)
{
    Bounds bounds;
    for (const std::vector<glm::vec3>& pose : animation.poses)
        for (const glm::vec3& p : pose)
            bounds.extend(glm::dvec3(p));
    return bounds;
}

std::shared_ptr<const LoadedScene> restSceneOf(const MeshAnimation& animation, const std::string& source)
{
    const std::string name = displayNameOf(source);
    return std::make_shared<LoadedScene>(animationPoseScene(animation, animation.restPose, name, name, source));
}

// The display of `animation` opened from `source`.
LoadedAnimation displayed(std::shared_ptr<const MeshAnimation> animation, const std::string& source, double loadMs)
{
    LoadedAnimation loaded;
    loaded.loadMs = loadMs;
    loaded.restScene = restSceneOf(*animation, source);
    loaded.bounds = poseBounds(*animation);
    if (std::optional<SkinningModel> skin = fileSkinningModel(*animation))
        loaded.fileSkin = std::make_shared<const SkinningModel>(std::move(*skin));
    loaded.animation = std::move(animation);
    return loaded;
}

} // namespace

LoadedAnimation loadAnimationForDisplay(const std::string& source, const TaskControl& control)
{
    const auto start = std::chrono::steady_clock::now();
    auto animation = std::make_shared<const MeshAnimation>(loadAnimation(source, {}, control));
    const double loadMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return displayed(std::move(animation), source, loadMs);
}

LoadedAnimation withHolesClosed(const LoadedAnimation& loaded, HoleClosing* closing)
{
    auto closed = std::make_shared<const MeshAnimation>(closeAnimationHoles(*loaded.animation, closing));
    return displayed(std::move(closed), loaded.restScene->source, loaded.loadMs);
}

} // namespace trimlab::ui
