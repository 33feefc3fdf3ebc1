#include "reference_scene_cache.h"

namespace trimlab::test {

ReferenceSceneCache::Entry& ReferenceSceneCache::built(const std::string& name)
{
    auto it = m_scenes.find(name);
    if (it == m_scenes.end())
        it = m_scenes.try_emplace(name, m_makeScene(name)).first;
    return it->second;
}

ReferenceSceneCache::Entry& ReferenceSceneCache::prepare(render::TrimRenderer& renderer, const std::string& name)
{
    Entry& entry = built(name);
    if (m_uploadedTo != &renderer || m_uploaded != name) {
        renderer.setScene(entry.scene);
        m_uploadedTo = &renderer;
        m_uploaded = name;
    }
    return entry;
}

const ReferenceResult& ReferenceSceneCache::referenceResult(const std::string& name, const std::string& settingsKey,
                                                            const Camera& camera, int width, int height,
                                                            const TrimSettings& settings)
{
    const std::string key = name + "/" + settingsKey;
    auto result = m_results.find(key);
    if (result == m_results.end())
        result = m_results.emplace(key, built(name).reference.render(camera, width, height, settings)).first;
    return result->second;
}

} // namespace trimlab::test
