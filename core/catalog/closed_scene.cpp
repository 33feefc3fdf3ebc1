#include "core/catalog/closed_scene.h"

#include "core/mesh/mesh_load_error.h"
#include "core/mesh/mesh_validation.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace trimlab {

HoleClosing closeSceneHoles(LoadedScene& loaded)
{
    HoleClosing total;
    std::vector<TriangleMesh> closed;
    closed.reserve(loaded.scene.objects.size());
    for (const SceneObject& object : loaded.scene.objects) {
        const std::string where = loaded.scene.objects.size() > 1 ? "object '" + object.name + "': " : std::string();
        HoleClosing closing;
        try {
            closed.push_back(closedMesh(object.mesh, &closing, where));
        } catch (const std::invalid_argument& e) {
            throw MeshLoadError(loaded.source, where + "cannot close its holes: " + e.what());
        }
        total += closing;
    }
    for (std::size_t i = 0; i < closed.size(); ++i) {
        loaded.scene.objects[i].mesh = std::move(closed[i]);
        loaded.reports[i] = validateMesh(loaded.scene.objects[i].mesh);
    }
    return total;
}

} // namespace trimlab
