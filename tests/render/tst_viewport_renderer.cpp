// The interactive view's renderer without the widget (render/viewport_renderer.h), on a
// real context: the content it keeps on the CPU — the scene, a pose, vertex colours, the
// dynamic rules' chain — goes into a new OpenGL context again and gives the same frame
// (what recovering from a GPU reset relies on), which agrees with the exact CPU reference
// of that content; out of memory it walks the fallback
// chain with a notice per step, down to the CPU still or, under the dynamic rules, a
// refusal; a new choice of parameters renders on the GPU again. The widget that carries
// this out is tested in ui.context_loss and ui.method_panel.
#include "gl_test_context.h"
#include "method_check.h"

#include "render/content_publisher.h"
#include "render/gl/gl_error.h"
#include "render/viewport_renderer.h"

#include "core/catalog/demo_scenes.h"
#include "core/skinning/skinning_reconstruction.h"
#include "core/skinning/skinning_weights.h"
#include "core/catalog/fig8_13_history.h"
#include "core/timeline/frame_chain.h"
#include "core/trim/dynamic_chain.h"
#include "core/trim/dynamic_reference_renderer.h"
#include "core/trim/reference_renderer.h"

#include <QtTest>

#include <memory>
#include <string>
#include <vector>

using namespace trimlab;
using namespace trimlab::render;

namespace {

constexpr QSize kSize(128, 96);

/// Pixels whose shown primitive, object, facing, winding or depth differ.
int differingPixels(const TrimImage& a, const TrimImage& b)
{
    if (a.width != b.width || a.height != b.height)
        return a.width * a.height + 1;
    int differ = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        const TrimPixel& p = a.pixels[i];
        const TrimPixel& q = b.pixels[i];
        differ += p.primitiveId != q.primitiveId || p.objectId != q.objectId || p.facing != q.facing ||
                          p.windingAtStart != q.windingAtStart || p.viewDepth != q.viewDepth
                      ? 1
                      : 0;
    }
    return differ;
}

/// The frame in `view`'s renderer against `reference` (test/method_check.h criteria).
std::optional<QString> frameDisagreement(ViewportRenderer& view, const QString& name, const Camera& camera,
                                         const TrimSettings& settings, const ReferenceResult& reference)
{
    const test::MethodCase testCase{name, camera, settings, view.methodParameters(), kSize.width(), kSize.height()};
    return test::checkFrameAgainstReference(view.renderer(), testCase, reference, {});
}

// Object 0 of `scene` in two bones (x < 0, x >= 0) along a pose-to-pose DQS chain whose
// poses turn the second bone 35° further each.
SkinningModel twoBoneModel(const Scene& scene, std::size_t poses)
{
    const TriangleMesh& mesh = scene.objects.front().mesh;
    VertexLabeling halves;
    halves.count = 2;
    for (const glm::vec3& p : mesh.positions)
        halves.labels.push_back(p.x < 0.0f ? 0u : 1u);
    SkinningModel model =
        identitySkinningModel(SkinningMethod::Dqs, SkinningChain::PoseToPose, poses, 0,
                              toDoublePositions(mesh.positions), rigidWeights(halves), mesh.triangles);
    for (std::size_t t = 1; t < poses; ++t)
        model.rigid[t][1] =
            dualQuaternionFromRigid(glm::angleAxis(glm::radians(35.0), glm::dvec3(0.0, 0.0, 1.0)), glm::dvec3(0.0));
    return model;
}

std::vector<glm::vec3> floatPositions(const PosePositions& positions)
{
    return {positions.begin(), positions.end()};
}

int coveredPixels(const TrimImage& image)
{
    int covered = 0;
    for (const TrimPixel& p : image.pixels)
        covered += p.covered() ? 1 : 0;
    return covered;
}

} // namespace

class TestViewportRenderer : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void contentGoesIntoANewContext();
    void layersShowTheirDominantOwner();
    void dynamicChainGoesIntoANewContext();
    void dragThenAppendUploadsOnlyTheChange();
    void skinnedPosesAreSkinnedOnTheGpu();
    void outOfMemoryWalksTheChainWithNotices();
    void dynamicRulesOutOfMemoryAreRefused();

private:
    /// Renders one frame and returns its trim image; `notices` receives the notices.
    TrimImage renderFrame(ViewportRenderer& view, const Camera& camera, std::vector<std::string>* notices = nullptr);

    std::unique_ptr<OffscreenGlContext> m_gl;
};

void TestViewportRenderer::initTestCase()
{
    TRIMLAB_INIT_GL_CONTEXT(m_gl);
}

TrimImage TestViewportRenderer::renderFrame(ViewportRenderer& view, const Camera& camera,
                                            std::vector<std::string>* notices)
{
    const bool rendered = view.render(camera, kSize, 0, [&](const std::string& notice) {
        if (notices)
            notices->push_back(notice);
    });
    if (rendered)
        view.finishFrames(); // the frame's results, so that lastFrame() is this frame
    if (!rendered || !view.lastFrame())
        return {};
    return view.renderer().readTrimImage();
}

// A pose (object 0 moved) and colours set before the first frame must reach the second
// context too: without them the frame differs, so the comparison sees a missed upload.
void TestViewportRenderer::contentGoesIntoANewContext()
{
    auto scene = std::make_shared<const Scene>(*makeDemoScene("pushed-sphere"));
    const Camera camera = fitCamera(scene->worldBounds(), double(kSize.width()) / kSize.height());
    const auto content = std::make_shared<ShownContent>();
    ViewportRenderer view(content);
    content->setScene(scene);
    ContentPublisher shown(content, ContentOwner::AnimationPlayback);
    m_gl->makeCurrent();
    view.initialize(m_gl->context());
    const TrimImage unposed = renderFrame(view, camera);
    QVERIFY(coveredPixels(unposed) > 1000);

    std::vector<glm::vec3> pose = scene->objects.front().mesh.positions;
    for (glm::vec3& p : pose)
        p.x += 0.25f;
    shown.showPose(pose);
    shown.showColors(std::vector<std::uint32_t>(pose.size(), 0xff2080ffu));
    const TrimImage posed = renderFrame(view, camera);
    QVERIFY(differingPixels(posed, unposed) > 100);
    const QImage posedColor = view.renderer().readColor();

    view.release(); // the context is lost; the content stays
    QVERIFY(!view.hasRenderer());
    OffscreenGlContext second;
    second.makeCurrent();
    view.initialize(second.context());
    const TrimImage again = renderFrame(view, camera);
    QCOMPARE(differingPixels(again, posed), 0);
    QVERIFY(view.renderer().readColor() == posedColor);
    // What was uploaded again is the content itself: the posed scene's exact reference.
    const ReferenceResult reference =
        ReferenceRenderer(*content->posedScene()).render(camera, kSize.width(), kSize.height(), TrimSettings{});
    const std::optional<QString> failure =
        frameDisagreement(view, QStringLiteral("viewport_renderer_posed"), camera, TrimSettings{}, reference);
    QVERIFY2(!failure, qPrintable(failure.value_or(QString())));
    view.release();
}

// Two owners publish poses and colours: the frame shows the last publisher's; when it
// withdraws, the frame is again the one of the owner before it, bit for bit, and with no
// pose left object 0 is back at the scene's own positions.
void TestViewportRenderer::layersShowTheirDominantOwner()
{
    auto scene = std::make_shared<const Scene>(*makeDemoScene("pushed-sphere"));
    const Camera camera = fitCamera(scene->worldBounds(), double(kSize.width()) / kSize.height());
    const auto content = std::make_shared<ShownContent>();
    ViewportRenderer view(content);
    content->setScene(scene);
    ContentPublisher skeleton(content, ContentOwner::Skeleton);
    ContentPublisher design(content, ContentOwner::DesignHistory);
    m_gl->makeCurrent();
    view.initialize(m_gl->context());
    const TrimImage rest = renderFrame(view, camera);
    const QImage restColor = view.renderer().readColor();

    std::vector<glm::vec3> moved = scene->objects.front().mesh.positions;
    for (glm::vec3& p : moved)
        p.x += 0.25f;
    std::vector<glm::vec3> lifted = scene->objects.front().mesh.positions;
    for (glm::vec3& p : lifted)
        p.y += 0.3f;
    skeleton.showPose(moved);
    skeleton.showColors(std::vector<std::uint32_t>(moved.size(), 0xff2080ffu));
    const TrimImage skeletonFrame = renderFrame(view, camera);
    const QImage skeletonColor = view.renderer().readColor();
    QVERIFY(differingPixels(skeletonFrame, rest) > 100);
    QVERIFY(skeletonColor != restColor);

    design.showPose(lifted);
    design.showColors(std::vector<std::uint32_t>(lifted.size(), 0xff20ff20u));
    QCOMPARE(content->poseOwner(), ContentOwner::DesignHistory);
    QCOMPARE(content->colorOwner(), ContentOwner::DesignHistory);
    const TrimImage designFrame = renderFrame(view, camera);
    QVERIFY(differingPixels(designFrame, skeletonFrame) > 100);
    QVERIFY(content->posedScene()->objects.front().mesh.positions == lifted);
    const ReferenceResult reference =
        ReferenceRenderer(*content->posedScene()).render(camera, kSize.width(), kSize.height(), TrimSettings{});
    const std::optional<QString> failure =
        frameDisagreement(view, QStringLiteral("viewport_renderer_dominant"), camera, TrimSettings{}, reference);
    QVERIFY2(!failure, qPrintable(failure.value_or(QString())));

    const std::uint64_t designVersion = content->version(ShownLayer::Pose);
    skeleton.showPose(moved); // the skeleton published last: its pose is shown
    QCOMPARE(content->poseOwner(), ContentOwner::Skeleton);
    const std::uint64_t skeletonVersion = content->version(ShownLayer::Pose);
    QVERIFY(skeletonVersion != designVersion);
    design.withdrawPose(); // not shown: nothing changes, nothing is uploaded
    QCOMPARE(content->version(ShownLayer::Pose), skeletonVersion);
    design.showColors({}); // shown: the skeleton's colours come back
    QCOMPARE(content->colorOwner(), ContentOwner::Skeleton);
    QCOMPARE(differingPixels(renderFrame(view, camera), skeletonFrame), 0);
    QVERIFY(view.renderer().readColor() == skeletonColor);

    skeleton.withdrawPose();
    skeleton.showColors({});
    QCOMPARE(content->poseOwner(), ContentOwner::None);
    QCOMPARE(content->colorOwner(), ContentOwner::None);
    QVERIFY(content->posedScene() == content->scene());
    QCOMPARE(differingPixels(renderFrame(view, camera), rest), 0);
    QVERIFY(view.renderer().readColor() == restColor);
    view.release();
}

// A skinned pose is evaluated on the GPU (no vertex upload), also in a new context, and
// trims like the exact reference of the CPU's pose; a model the GPU cannot skin for the
// object falls back to the CPU's positions.
void TestViewportRenderer::skinnedPosesAreSkinnedOnTheGpu()
{
    auto scene = std::make_shared<const Scene>(*makeDemoScene("pushed-sphere"));
    auto model = std::make_shared<const SkinningModel>(twoBoneModel(*scene, 3));
    const std::vector<PosePositions> cpu = reconstructPoses(*model);
    const Camera camera = fitCamera(scene->worldBounds(), double(kSize.width()) / kSize.height());
    const auto content = std::make_shared<ShownContent>();
    ViewportRenderer view(content);
    content->setScene(scene);
    ContentPublisher shown(content, ContentOwner::Skinning);
    m_gl->makeCurrent();
    view.initialize(m_gl->context());
    const TrimImage rest = renderFrame(view, camera);
    const auto agreesWithCpuPose = [&](const char* name) {
        const ReferenceResult reference =
            ReferenceRenderer(*content->posedScene()).render(camera, kSize.width(), kSize.height(), TrimSettings{});
        return frameDisagreement(view, QString::fromLatin1(name), camera, TrimSettings{}, reference);
    };

    for (std::size_t pose : {1u, 2u}) { // playback: one chain step each
        shown.showSkinnedPose(model, pose, floatPositions(cpu[pose]));
        const TrimImage skinned = renderFrame(view, camera);
        QCOMPARE(view.lastPoseEvaluation(), PoseEvaluation::GpuSkinning);
        QVERIFY(differingPixels(skinned, rest) > 100);
        const std::optional<QString> failure = agreesWithCpuPose("viewport_renderer_skinned");
        QVERIFY2(!failure, qPrintable(failure.value_or(QString())));
    }

    view.release();
    OffscreenGlContext second;
    second.makeCurrent();
    view.initialize(second.context());
    renderFrame(view, camera);
    QCOMPARE(view.lastPoseEvaluation(), PoseEvaluation::GpuSkinning);
    std::optional<QString> failure = agreesWithCpuPose("viewport_renderer_skinned_again");
    QVERIFY2(!failure, qPrintable(failure.value_or(QString())));

    SkinningModel mismatched = *model; // not object 0's mesh: the CPU's pose is shown
    mismatched.triangles.pop_back();
    shown.showSkinnedPose(std::make_shared<const SkinningModel>(std::move(mismatched)), 1, floatPositions(cpu[1]));
    renderFrame(view, camera);
    QCOMPARE(view.lastPoseEvaluation(), PoseEvaluation::Uploaded);
    failure = agreesWithCpuPose("viewport_renderer_skinned_fallback");
    QVERIFY2(!failure, qPrintable(failure.value_or(QString())));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, shown.showSkinnedPose(model, 3, floatPositions(cpu[1])));
    view.release();
}

// Under the dynamic rules the chain's levels are uploaded anew in a new context.
void TestViewportRenderer::dynamicChainGoesIntoANewContext()
{
    const timeline::Timeline history = fig8_13NurbsHistory();
    const int last = history.frameCount() - 1;
    auto chain = std::make_shared<const DynamicChain>(timeline::frameChain(history, last, StaticRule::Parity));
    auto scene = std::make_shared<const Scene>(timeline::frameScene(history, last));
    const Camera camera = fitCamera(timeline::chainBounds(*chain), double(kSize.width()) / kSize.height());
    TrimSettings settings;
    settings.rule = StaticRule::Parity;
    const auto content = std::make_shared<ShownContent>();
    ViewportRenderer view(content);
    content->setScene(scene);
    view.setTrimSettings(settings);
    view.setMethod(FragmentMethodKind::SBuffer);
    ContentPublisher(content, ContentOwner::DesignHistory).showChain(chain);
    m_gl->makeCurrent();
    view.initialize(m_gl->context());
    const TrimImage first = renderFrame(view, camera);
    QVERIFY(view.lastDynamicStats().has_value());
    QVERIFY(coveredPixels(first) > 500);
    view.release();
    OffscreenGlContext second;
    second.makeCurrent();
    view.initialize(second.context());
    const TrimImage again = renderFrame(view, camera);
    QVERIFY(view.lastDynamicStats().has_value());
    QCOMPARE(differingPixels(again, first), 0);
    const ReferenceResult reference =
        DynamicReferenceRenderer(*chain).render(camera, kSize.width(), kSize.height(), settings);
    const std::optional<QString> failure =
        frameDisagreement(view, QStringLiteral("viewport_renderer_dynamic"), camera, settings, reference);
    QVERIFY2(!failure, qPrintable(failure.value_or(QString())));
    view.release();
}

// A drag replaces the shown level and playback appends a level before the next frame:
// the renderer uploads both into the chain it holds (one characterization pass for the
// replaced level, now a reference), and the frame is the one of the whole chain, which
// agrees with the exact reference.
void TestViewportRenderer::dragThenAppendUploadsOnlyTheChange()
{
    const timeline::Timeline history = fig8_13NurbsHistory();
    const std::vector<glm::uvec3>& triangles = history.base().triangles;
    std::vector<std::vector<glm::vec3>> frames;
    for (int f = 0; f < history.frameCount(); ++f)
        frames.push_back(history.positionsAt(f));
    QCOMPARE(frames.size(), std::size_t(5));
    const auto chainOf = [&](std::vector<int> shown) {
        std::vector<std::vector<glm::vec3>> positions;
        for (int f : shown)
            positions.push_back(frames[std::size_t(f)]);
        return makeDynamicChain(triangles, positions,
                                std::vector<DynamicRule>(shown.size() - 1, DynamicRule::Confluent), StaticRule::Parity);
    };
    const auto first = std::make_shared<const DynamicChain>(chainOf({0, 1, 2}));
    const DynamicChain dragged = chainOf({0, 1, 3});
    const DynamicChain whole = chainOf({0, 1, 3, 4});
    const Camera camera = fitCamera(timeline::chainBounds(whole), double(kSize.width()) / kSize.height());
    TrimSettings settings;
    settings.rule = StaticRule::Parity;
    const auto content = std::make_shared<ShownContent>();
    ViewportRenderer view(content);
    content->setScene(std::make_shared<const Scene>(timeline::frameScene(history, 2)));
    view.setTrimSettings(settings);
    view.setMethod(FragmentMethodKind::SBuffer);
    ContentPublisher design(content, ContentOwner::DesignHistory);
    design.showChain(first);
    m_gl->makeCurrent();
    view.initialize(m_gl->context());
    QVERIFY(coveredPixels(renderFrame(view, camera)) > 500);
    QCOMPARE(view.lastDynamicStats()->characterizedLevels, 1);

    design.replaceShownLevel(std::make_shared<const DynamicChainLevel>(dragged.levels.back()));
    design.appendLevel(std::make_shared<const DynamicChainLevel>(whole.levels.back()));
    QCOMPARE(content->chain()->levels.size(), std::size_t(3));
    const TrimImage appended = renderFrame(view, camera);
    QCOMPARE(view.lastDynamicStats()->levels, 3);
    QCOMPARE(view.lastDynamicStats()->characterizedLevels, 1); // level 0's characterization stayed
    const ReferenceResult reference =
        DynamicReferenceRenderer(whole).render(camera, kSize.width(), kSize.height(), settings);
    const std::optional<QString> failure =
        frameDisagreement(view, QStringLiteral("viewport_renderer_drag_append"), camera, settings, reference);
    QVERIFY2(!failure, qPrintable(failure.value_or(QString())));

    design.showChain(std::make_shared<const DynamicChain>(whole)); // the same chain, published whole
    QCOMPARE(differingPixels(renderFrame(view, camera), appended), 0);
    QCOMPARE(view.lastDynamicStats()->characterizedLevels, 2);
    view.release();
}

// A budget no method fits: every step of the chain is announced, then the CPU still; a
// choice without the budget renders on the GPU again.
void TestViewportRenderer::outOfMemoryWalksTheChainWithNotices()
{
    auto scene = std::make_shared<const Scene>(*makeDemoScene("pushed-sphere"));
    const Camera camera = fitCamera(scene->worldBounds(), double(kSize.width()) / kSize.height());
    const auto content = std::make_shared<ShownContent>();
    ViewportRenderer view(content);
    content->setScene(scene);
    MethodParameters tiny;
    tiny.memoryBudgetBytes = 1;
    view.setMethodParameters(tiny);
    m_gl->makeCurrent();
    view.initialize(m_gl->context());
    std::vector<std::string> notices;
    QVERIFY(!view.render(camera, kSize, 0, [&](const std::string& notice) { notices.push_back(notice); }));
    QVERIFY(view.policy().showsCpuStill());
    QVERIFY(!view.lastFrame());
    // k⁺-buffer → S-buffer → F2B peeling → the CPU still: three notices.
    QCOMPARE(notices.size(), std::size_t(3));
    QVERIFY(notices.back().find("CPU reference") != std::string::npos);
    QCOMPARE(view.policy().chosenMethod(), FragmentMethodKind::KPlusArray);

    view.setMethodParameters(MethodParameters{});
    QVERIFY(!view.policy().showsCpuStill());
    QVERIFY(coveredPixels(renderFrame(view, camera, &notices)) > 1000);
    QCOMPARE(notices.size(), std::size_t(3));
    view.release();
}

void TestViewportRenderer::dynamicRulesOutOfMemoryAreRefused()
{
    const timeline::Timeline history = fig8_13NurbsHistory();
    const int last = history.frameCount() - 1;
    auto chain = std::make_shared<const DynamicChain>(timeline::frameChain(history, last, StaticRule::Parity));
    const Camera camera = fitCamera(timeline::chainBounds(*chain), double(kSize.width()) / kSize.height());
    const auto content = std::make_shared<ShownContent>();
    ViewportRenderer view(content);
    content->setScene(std::make_shared<const Scene>(timeline::frameScene(history, last)));
    MethodParameters tiny;
    tiny.memoryBudgetBytes = 1;
    view.setMethodParameters(tiny);
    ContentPublisher(content, ContentOwner::DesignHistory).showChain(chain);
    m_gl->makeCurrent();
    view.initialize(m_gl->context());
    std::vector<std::string> notices;
    try {
        (void)view.render(camera, kSize, 0, [&](const std::string& notice) { notices.push_back(notice); });
        QFAIL("a frame no method fits rendered under the dynamic rules");
    } catch (const GpuMemoryError& e) {
        QVERIFY2(std::string(e.what()).find("No GPU method with the dynamic rules fits") != std::string::npos,
                 e.what());
    }
    QCOMPARE(notices.size(), std::size_t(1)); // k⁺-buffer → S-buffer, then the refusal
    QVERIFY(!view.policy().showsCpuStill());
    view.release();
}

QTEST_MAIN(TestViewportRenderer)
#include "tst_viewport_renderer.moc"
