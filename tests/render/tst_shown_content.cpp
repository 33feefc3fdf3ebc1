// The shown content without a GPU (render/shown_content.h): each layer shows its dominant
// owner's content — the last publisher among those still publishing —, a withdrawal gives
// the layer back to the owner before, versions change exactly when what a layer shows
// changes, a new scene empties the layers, the posed scene is the scene with the shown
// pose, listeners hear of every change (also of one a listener makes), and bad content
// is refused with the counts in the message.
#include "render/content_publisher.h"
#include "render/shown_content.h"

#include "core/catalog/demo_scenes.h"

#include <QtTest>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

using namespace trimlab;
using namespace trimlab::render;

namespace {

std::vector<glm::vec3> shifted(const std::vector<glm::vec3>& positions, float dx)
{
    std::vector<glm::vec3> moved = positions;
    for (glm::vec3& p : moved)
        p.x += dx;
    return moved;
}

/// A one-level chain whose shown frame has `positions` (its geometry is not looked at here).
std::shared_ptr<const DynamicChain> oneLevelChain(const TriangleMesh& mesh)
{
    return std::make_shared<const DynamicChain>(makeDynamicChain(
        mesh.triangles, {mesh.positions, shifted(mesh.positions, 0.1f)}, {DynamicRule::Confluent}, StaticRule::Parity));
}

} // namespace

class TestShownContent : public QObject {
    Q_OBJECT
private slots:
    void init();
    void thePoseOfTheLastPublisherIsShown();
    void colorsAndChainsFollowTheSameRule();
    void aNewSceneEmptiesEveryLayer();
    void dragsAndPlaybackChangeTheChainInPlace();
    void listenersHearEveryChange();
    void badContentIsRefused();

private:
    std::shared_ptr<ShownContent> m_content;
    std::shared_ptr<const Scene> m_scene;
};

void TestShownContent::init()
{
    m_scene = std::make_shared<const Scene>(*makeDemoScene("pushed-sphere"));
    m_content = std::make_shared<ShownContent>();
    m_content->setScene(m_scene);
}

void TestShownContent::thePoseOfTheLastPublisherIsShown()
{
    ContentPublisher design(m_content, ContentOwner::DesignHistory);
    ContentPublisher skeleton(m_content, ContentOwner::Skeleton);
    const std::vector<glm::vec3>& rest = m_scene->objects.front().mesh.positions;
    QCOMPARE(m_content->poseOwner(), ContentOwner::None);
    QVERIFY(m_content->posedScene() == m_scene); // no pose: the scene itself

    const std::uint64_t before = m_content->version(ShownLayer::Pose);
    design.showPose(shifted(rest, 0.5f));
    QVERIFY(m_content->version(ShownLayer::Pose) != before);
    QCOMPARE(m_content->poseOwner(), ContentOwner::DesignHistory);
    QVERIFY(design.showsPose() && !skeleton.showsPose());
    skeleton.showPose(shifted(rest, -0.5f));
    QCOMPARE(m_content->poseOwner(), ContentOwner::Skeleton);
    const std::shared_ptr<const Scene> posed = m_content->posedScene();
    QVERIFY(posed != m_scene);
    QVERIFY(posed->objects.front().mesh.positions == shifted(rest, -0.5f));
    QVERIFY(posed->objects.front().mesh.triangles == m_scene->objects.front().mesh.triangles);
    QVERIFY(m_content->posedScene() == posed); // kept while nothing changes

    const std::uint64_t skeletonShown = m_content->version(ShownLayer::Pose);
    design.withdrawPose(); // not shown: nothing changes
    QCOMPARE(m_content->version(ShownLayer::Pose), skeletonShown);
    QCOMPARE(m_content->poseOwner(), ContentOwner::Skeleton);
    design.showPose(shifted(rest, 0.25f));
    QCOMPARE(m_content->poseOwner(), ContentOwner::DesignHistory);
    design.withdrawPose(); // shown: the skeleton's pose comes back, unchanged
    QCOMPARE(m_content->poseOwner(), ContentOwner::Skeleton);
    QVERIFY(m_content->pose()->positions == shifted(rest, -0.5f));
    QVERIFY(m_content->posedScene()->objects.front().mesh.positions == shifted(rest, -0.5f));
    skeleton.withdrawPose();
    QCOMPARE(m_content->poseOwner(), ContentOwner::None);
    QVERIFY(m_content->posedScene() == m_scene);

    ContentPublisher unconnected;
    unconnected.showPose(rest); // publishes nothing
    QCOMPARE(m_content->poseOwner(), ContentOwner::None);
    QVERIFY(!unconnected.showsPose());
}

void TestShownContent::colorsAndChainsFollowTheSameRule()
{
    ContentPublisher segments(m_content, ContentOwner::Segmentation);
    ContentPublisher brush(m_content, ContentOwner::BrushRegion);
    const std::size_t vertices = m_scene->objects.front().mesh.vertexCount();
    segments.showColors(std::vector<std::uint32_t>(vertices, 1u));
    brush.showColors(std::vector<std::uint32_t>(vertices, 2u));
    QCOMPARE(m_content->colorOwner(), ContentOwner::BrushRegion);
    QCOMPARE(m_content->colors()->front(), 2u);
    brush.showColors({}); // empty: withdrawn
    QCOMPARE(m_content->colorOwner(), ContentOwner::Segmentation);
    QCOMPARE(m_content->colors()->front(), 1u);
    QVERIFY(segments.showsColors() && !brush.showsColors());

    ContentPublisher design(m_content, ContentOwner::DesignHistory);
    ContentPublisher playback(m_content, ContentOwner::AnimationPlayback);
    const std::shared_ptr<const DynamicChain> chain = oneLevelChain(m_scene->objects.front().mesh);
    design.showChain(chain);
    const std::uint64_t designId = m_content->chain()->id;
    playback.showChain(chain);
    QCOMPARE(m_content->chainOwner(), ContentOwner::AnimationPlayback);
    QVERIFY(m_content->chain()->id != designId); // another publication, another upload
    playback.showChain(nullptr);
    QCOMPARE(m_content->chainOwner(), ContentOwner::DesignHistory);
    QCOMPARE(m_content->chain()->id, designId);
    QVERIFY(design.showsChain());
}

void TestShownContent::aNewSceneEmptiesEveryLayer()
{
    ContentPublisher skeleton(m_content, ContentOwner::Skeleton);
    const TriangleMesh& mesh = m_scene->objects.front().mesh;
    skeleton.showPose(shifted(mesh.positions, 1.0f));
    skeleton.showColors(std::vector<std::uint32_t>(mesh.vertexCount(), 3u));
    skeleton.showChain(oneLevelChain(mesh));
    const std::uint64_t meshes = m_content->meshVersion();
    const std::uint64_t geometry = m_content->version(ShownLayer::Geometry);

    auto moved = std::make_shared<Scene>(*m_scene);
    moved->objects.front().modelMatrix[3].x = 2.0;
    m_content->setSceneTransforms(moved); // the same meshes elsewhere: the layers stay
    QCOMPARE(m_content->meshVersion(), meshes);
    QVERIFY(m_content->version(ShownLayer::Geometry) != geometry);
    QCOMPARE(m_content->poseOwner(), ContentOwner::Skeleton);
    QCOMPARE(m_content->posedScene()->objects.front().modelMatrix[3].x, 2.0);

    m_content->setScene(std::make_shared<const Scene>(*makeDemoScene("pushed-sphere")));
    QVERIFY(m_content->meshVersion() != meshes);
    QCOMPARE(m_content->poseOwner(), ContentOwner::None);
    QCOMPARE(m_content->colorOwner(), ContentOwner::None);
    QCOMPARE(m_content->chainOwner(), ContentOwner::None);
    skeleton.withdrawPose(); // nothing left to withdraw: harmless
    QCOMPARE(m_content->poseOwner(), ContentOwner::None);
}

void TestShownContent::dragsAndPlaybackChangeTheChainInPlace()
{
    ContentPublisher design(m_content, ContentOwner::DesignHistory);
    ContentPublisher skeleton(m_content, ContentOwner::Skeleton);
    const TriangleMesh& mesh = m_scene->objects.front().mesh;
    const std::shared_ptr<const DynamicChain> chain = oneLevelChain(mesh);
    const auto level = std::make_shared<const DynamicChainLevel>(chain->levels.back());

    design.replaceShownLevel(level); // no chain of its own: ignored
    QCOMPARE(m_content->chainOwner(), ContentOwner::None);
    design.showChain(chain);
    const std::uint64_t id = m_content->chain()->id;
    QVERIFY(&m_content->chain()->shownLevel() == &chain->levels.back());
    design.replaceShownLevel(level);
    QVERIFY(&m_content->chain()->shownLevel() == level.get());
    design.appendLevel(level);
    QCOMPARE(m_content->chain()->levels.size(), std::size_t(2));
    QCOMPARE(m_content->chain()->id, id); // the same chain, changed in place
    const std::uint64_t version = m_content->version(ShownLayer::Chain);
    skeleton.appendLevel(level); // another owner has no chain here: ignored
    QCOMPARE(m_content->version(ShownLayer::Chain), version);
    QCOMPARE(m_content->chain()->levels.size(), std::size_t(2));
}

void TestShownContent::listenersHearEveryChange()
{
    ContentPublisher design(m_content, ContentOwner::DesignHistory);
    ContentPublisher skeleton(m_content, ContentOwner::Skeleton);
    const std::vector<glm::vec3>& rest = m_scene->objects.front().mesh.positions;
    std::vector<ShownLayer> heard;
    ContentSubscription subscription = m_content->subscribe([&](ShownLayer layer) {
        heard.push_back(layer);
        if (layer == ShownLayer::Pose && m_content->poseOwner() == ContentOwner::Skeleton)
            design.showColors(std::vector<std::uint32_t>(rest.size(), 4u)); // a listener publishes
    });
    skeleton.showPose(rest);
    QVERIFY(heard == (std::vector<ShownLayer>{ShownLayer::Pose, ShownLayer::Colors}));
    QCOMPARE(m_content->colorOwner(), ContentOwner::DesignHistory);
    design.withdrawPose(); // nothing shown changes: nothing to hear
    QCOMPARE(heard.size(), std::size_t(2));
    {
        ContentSubscription moved = std::move(subscription);
        m_content->setScene(m_scene);
        QCOMPARE(heard.size(), std::size_t(6)); // the geometry and the three layers it emptied
    }
    skeleton.showPose(rest); // the subscription went with `moved`
    QCOMPARE(heard.size(), std::size_t(6));

    ContentSubscription outlives = m_content->subscribe([](ShownLayer) {});
    m_content.reset(); // the content goes first: the subscription's end is harmless
}

void TestShownContent::badContentIsRefused()
{
    ContentPublisher design(m_content, ContentOwner::DesignHistory);
    const TriangleMesh& mesh = m_scene->objects.front().mesh;
    try {
        design.showPose({glm::vec3(0.0f)});
        QFAIL("a pose of one vertex was taken");
    } catch (const std::invalid_argument& e) {
        QVERIFY2(std::string(e.what()).find(std::to_string(mesh.vertexCount())) != std::string::npos, e.what());
    }
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, design.showColors({1u, 2u}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, design.showSkinnedPose(nullptr, 0, mesh.positions));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             design.showSubdivisionPose(nullptr, {glm::dvec3(0.0)}, mesh.positions));
    QCOMPARE(m_content->poseOwner(), ContentOwner::None);
    QCOMPARE(m_content->colorOwner(), ContentOwner::None);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, m_content->setSceneTransforms(nullptr));
    auto fewer = std::make_shared<Scene>(*m_scene);
    fewer->objects.front().mesh.triangles.pop_back();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, m_content->setSceneTransforms(fewer));

    ShownContent empty;
    ContentPublisher nowhere(std::shared_ptr<ShownContent>(&empty, [](ShownContent*) {}), ContentOwner::Skeleton);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, nowhere.showPose(mesh.positions)); // no scene
}

QTEST_APPLESS_MAIN(TestShownContent)
#include "tst_shown_content.moc"
