#pragma once
/// \file
/// The scene cache of render tests that run many cases per scene: each scene is built
/// once, with its exact CPU reference renderer; each (scene, settings) reference image is
/// computed once; and a scene is uploaded to the GPU renderer only when the case before
/// used another one (an upload rebuilds the renderer's buffers).

#include "render/trim_renderer.h"

#include "core/scene/scene.h"
#include "core/trim/reference_renderer.h"

#include <functional>
#include <map>
#include <string>

namespace trimlab::test {

class ReferenceSceneCache {
public:
    /// A scene and the reference renderer built from it (which copies what it needs).
    struct Entry {
        explicit Entry(Scene built) : scene(std::move(built)), reference(scene) {}

        Scene scene;
        ReferenceRenderer reference;
    };

    /// Builds the scene of a name used in the test's cases (a demo name, a mesh file);
    /// called once per name. It may throw, failing the test case that asked for it.
    using SceneFactory = std::function<Scene(const std::string& name)>;

    explicit ReferenceSceneCache(SceneFactory makeScene) : m_makeScene(std::move(makeScene)) {}

    /// The scene `name` (built on first use), made the scene of `renderer` unless it
    /// already is — as far as this cache knows: it tracks only its own uploads.
    Entry& prepare(render::TrimRenderer& renderer, const std::string& name);

    /// The reference image of scene `name` rendered with `camera`, `width`×`height` and
    /// `settings`, computed on first use and then kept under (`name`, `settingsKey`): the
    /// caller names the settings and must not reuse a key for another camera, size or
    /// settings.
    const ReferenceResult& referenceResult(const std::string& name, const std::string& settingsKey,
                                           const Camera& camera, int width, int height, const TrimSettings& settings);

private:
    /// The entry of `name`, building it on first use.
    Entry& built(const std::string& name);

    SceneFactory m_makeScene;
    std::map<std::string, Entry> m_scenes;
    std::map<std::string, ReferenceResult> m_results; ///< by "scene/settings"
    const render::TrimRenderer* m_uploadedTo = nullptr;
    std::string m_uploaded;
};

} // namespace trimlab::test
