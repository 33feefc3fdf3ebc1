#include "render/shown_content.h"

#include <stdexcept>
#include <string>

namespace trimlab::render {

/// The listeners of one ShownContent. A listener removed while they are being told (its
/// subscription went) is only blanked then, and dropped after.
struct ContentSubscription::Listeners {
    std::vector<std::pair<int, ShownContent::Listener>> entries;
    int nextId = 1;
    int telling = 0; ///< nesting depth of ShownContent::changed

    void remove(int id)
    {
        for (auto& entry : entries)
            if (entry.first == id)
                entry.second = nullptr;
        if (telling == 0)
            std::erase_if(entries, [](const auto& entry) { return !entry.second; });
    }
};

ContentSubscription::~ContentSubscription()
{
    reset();
}

ContentSubscription::ContentSubscription(ContentSubscription&& other) noexcept
    : m_listeners(std::move(other.m_listeners)), m_id(std::exchange(other.m_id, 0))
{
}

ContentSubscription& ContentSubscription::operator=(ContentSubscription&& other) noexcept
{
    if (this != &other) {
        reset();
        m_listeners = std::move(other.m_listeners);
        m_id = std::exchange(other.m_id, 0);
    }
    return *this;
}

void ContentSubscription::reset()
{
    if (const std::shared_ptr<Listeners> listeners = m_listeners.lock())
        listeners->remove(m_id);
    m_listeners.reset();
    m_id = 0;
}

ShownContent::ShownContent() : m_listeners(std::make_shared<ContentSubscription::Listeners>())
{
}

ShownContent::~ShownContent() = default;

ContentSubscription ShownContent::subscribe(Listener listener) const
{
    const int id = m_listeners->nextId++;
    m_listeners->entries.emplace_back(id, std::move(listener));
    return ContentSubscription(m_listeners, id);
}

// Told by index, each listener copied before the call: a listener may subscribe (the
// vector grows) or publish (the change is told in turn) while the others wait.
void ShownContent::changed(ShownLayer layer)
{
    const std::shared_ptr<ContentSubscription::Listeners> listeners = m_listeners;
    ++listeners->telling;
    for (std::size_t i = 0; i < listeners->entries.size(); ++i) {
        const Listener listener = listeners->entries[i].second;
        if (listener)
            listener(layer);
    }
    if (--listeners->telling == 0)
        std::erase_if(listeners->entries, [](const auto& entry) { return !entry.second; });
}

void ShownContent::setScene(std::shared_ptr<const Scene> scene)
{
    m_scene = std::move(scene);
    const std::uint64_t stamp = ++m_stamp;
    m_geometryVersion = stamp;
    m_meshVersion = stamp;
    m_pose.clear(stamp);
    m_colors.clear(stamp);
    m_chain.clear(stamp);
    for (ShownLayer layer : {ShownLayer::Geometry, ShownLayer::Pose, ShownLayer::Colors, ShownLayer::Chain})
        changed(layer);
}

void ShownContent::setSceneTransforms(std::shared_ptr<const Scene> scene)
{
    if (!m_scene || !scene || scene->objects.size() != m_scene->objects.size())
        throw std::invalid_argument("setSceneTransforms: the new scene does not have the shown scene's objects.");
    for (std::size_t i = 0; i < scene->objects.size(); ++i) {
        if (scene->objects[i].mesh.vertexCount() != m_scene->objects[i].mesh.vertexCount() ||
            scene->objects[i].mesh.triangleCount() != m_scene->objects[i].mesh.triangleCount())
            throw std::invalid_argument("setSceneTransforms: object " + std::to_string(i) +
                                        " has another mesh than the one shown.");
    }
    m_scene = std::move(scene);
    m_geometryVersion = ++m_stamp;
    changed(ShownLayer::Geometry);
}

std::uint64_t ShownContent::version(ShownLayer layer) const
{
    switch (layer) {
    case ShownLayer::Geometry:
        return m_geometryVersion;
    case ShownLayer::Pose:
        return m_pose.version();
    case ShownLayer::Colors:
        return m_colors.version();
    case ShownLayer::Chain:
        return m_chain.version();
    }
    return 0;
}

std::shared_ptr<const Scene> ShownContent::posedScene() const
{
    const std::pair<std::uint64_t, std::uint64_t> versions{m_geometryVersion, m_pose.version()};
    if (versions == m_posedVersion)
        return m_posedScene;
    m_posedVersion = versions;
    m_posedScene = m_scene;
    if (m_scene && pose()) {
        auto posed = std::make_shared<Scene>(*m_scene);
        posed->objects.front().mesh.positions = pose()->positions;
        m_posedScene = std::move(posed);
    }
    return m_posedScene;
}

std::size_t ShownContent::objectZeroVertices() const
{
    return m_scene && !m_scene->objects.empty() ? m_scene->objects.front().mesh.vertexCount() : 0;
}

std::size_t ShownContent::sceneVertices() const
{
    std::size_t vertices = 0;
    if (m_scene)
        for (const SceneObject& object : m_scene->objects)
            vertices += object.mesh.vertexCount();
    return vertices;
}

void ShownContent::publishPose(ContentOwner owner, ShownPose pose)
{
    const std::size_t expected = objectZeroVertices();
    if (pose.positions.size() != expected || expected == 0)
        throw std::invalid_argument("showPose: the scene's first object has " + std::to_string(expected) +
                                    " vertices, the pose " + std::to_string(pose.positions.size()) + ".");
    if (const auto* skinned = std::get_if<SkinnedPose>(&pose.evaluation)) {
        if (!skinned->model || skinned->pose >= skinned->model->poseCount())
            throw std::invalid_argument("showSkinnedPose: pose " + std::to_string(skinned->pose) + " of a model with " +
                                        std::to_string(skinned->model ? skinned->model->poseCount() : 0) + " poses.");
    }
    if (const auto* surface = std::get_if<SubdivisionPose>(&pose.evaluation)) {
        if (!surface->stencils || surface->controlPoints.size() != surface->stencils->cageVertexCount)
            throw std::invalid_argument("showSubdivisionPose: " + std::to_string(surface->controlPoints.size()) +
                                        " control points for a cage of " +
                                        std::to_string(surface->stencils ? surface->stencils->cageVertexCount : 0) +
                                        ".");
    }
    m_pose.publish(owner, std::move(pose), ++m_stamp);
    changed(ShownLayer::Pose);
}

void ShownContent::withdrawPose(ContentOwner owner)
{
    if (m_pose.withdraw(owner, ++m_stamp))
        changed(ShownLayer::Pose);
}

void ShownContent::publishColors(ContentOwner owner, std::vector<std::uint32_t> rgba8)
{
    const std::size_t vertices = sceneVertices();
    if (rgba8.size() != vertices)
        throw std::invalid_argument("showColors: the scene has " + std::to_string(vertices) + " vertices, got " +
                                    std::to_string(rgba8.size()) + " colors.");
    m_colors.publish(owner, std::move(rgba8), ++m_stamp);
    changed(ShownLayer::Colors);
}

void ShownContent::withdrawColors(ContentOwner owner)
{
    if (m_colors.withdraw(owner, ++m_stamp))
        changed(ShownLayer::Colors);
}

void ShownContent::publishChain(ContentOwner owner, std::shared_ptr<const DynamicChain> chain)
{
    if (!chain || chain->levels.empty())
        throw std::invalid_argument("showChain: a dynamic chain needs at least one level.");
    ShownChain shown;
    shown.levels.reserve(chain->levels.size());
    for (const DynamicChainLevel& level : chain->levels)
        shown.levels.emplace_back(chain, &level); // shares the chain's ownership
    shown.chain = std::move(chain);
    shown.id = ++m_chainIds;
    m_chain.publish(owner, std::move(shown), ++m_stamp);
    changed(ShownLayer::Chain);
}

void ShownContent::withdrawChain(ContentOwner owner)
{
    if (m_chain.withdraw(owner, ++m_stamp))
        changed(ShownLayer::Chain);
}

void ShownContent::replaceShownLevel(ContentOwner owner, std::shared_ptr<const DynamicChainLevel> level)
{
    ShownChain* chain = m_chain.of(owner);
    if (!chain || !level)
        return;
    chain->levels.back() = std::move(level);
    if (m_chain.changed(owner, ++m_stamp))
        changed(ShownLayer::Chain);
}

void ShownContent::appendLevel(ContentOwner owner, std::shared_ptr<const DynamicChainLevel> level)
{
    ShownChain* chain = m_chain.of(owner);
    if (!chain || !level)
        return;
    chain->levels.push_back(std::move(level));
    if (m_chain.changed(owner, ++m_stamp))
        changed(ShownLayer::Chain);
}

} // namespace trimlab::render
