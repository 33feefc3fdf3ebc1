#pragma once
/// \file
/// A scene project (project format version 3): the scene the Scene panel shows, several
/// objects each with its mesh, placement and optional rule, and the CSG expression over
/// them, so that an assembly built with File ▸ Add Object saves and reopens as it was.

#include "core/scene/scene.h"
#include "core/trim/inspect_settings.h"

#include <vector>

namespace trimlab::timeline {

struct ProjectScene {
    /// 1 to Scene::maxObjects objects: name, mesh (float positions, stored bit for bit)
    /// and an orientation-preserving affine model matrix, stored as its 16 doubles.
    std::vector<SceneObject> objects;
    /// The CSG expression over object ids and the per-object rules (ids below
    /// kMaxCsgOperands; nullopt: the scene's rule).
    CsgSettings csg;

    friend bool operator==(const ProjectScene& a, const ProjectScene& b);
};

} // namespace trimlab::timeline
