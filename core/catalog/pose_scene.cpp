#include "core/catalog/pose_scene.h"

#include "core/mesh/mesh_validation.h"

#include <utility>

namespace trimlab {

LoadedScene animationPoseScene(const MeshAnimation& animation, std::size_t pose, const std::string& objectName,
                               std::string displayName, std::string source)
{
    LoadedScene loaded;
    loaded.source = std::move(source);
    loaded.displayName = std::move(displayName);
    loaded.scene.objects.push_back({objectName, animation.poseMesh(pose), glm::dmat4(1.0)});
    loaded.reports.push_back(validateMesh(loaded.scene.objects.front().mesh));
    return loaded;
}

} // namespace trimlab
