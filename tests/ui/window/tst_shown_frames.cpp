// What the view shows when several features pose the same mesh, in the real main window
// driven like a user: the Skeleton panel poses a closed star, a brush stroke and a frame
// change of the design history follow, the skeleton poses it again (also under the
// dynamic rules), then an animation plays. After each step the shown content names the
// step's feature as the pose's owner, its shown scene holds that feature's positions,
// and the frame rendered agrees with the exact reference of those positions — and not
// with the content shown before it.
#include "design_window.h"
#include "gl_test_context.h"
#include "meeting_balls.h"
#include "message_box_closer.h"
#include "named_child.h"
#include "plain_obj.h"
#include "posed_frame_check.h"
#include "skeleton_shapes.h"

#include "ui/common/background_job.h"
#include "ui/common/loaded_animation.h"
#include "ui/design/design_session.h"
#include "ui/design/design_workspace.h"
#include "ui/skeleton/skeleton_panel.h"
#include "ui/skeleton/skeleton_workspace.h"
#include "ui/viewport/viewport_widget.h"
#include "ui/window/main_window.h"

#include "render/shown_content.h"

#include "core/animation/mesh_animation.h"
#include "core/design/session_chain.h"

#include <QtTest>

#include <QComboBox>
#include <QDockWidget>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QTemporaryDir>

#include <glm/geometric.hpp>

using namespace trimlab;
using namespace trimlab::ui;
using render::ContentOwner;
using trimlab::test::child;
using trimlab::test::kWaitMs;

namespace {

constexpr QSize kViewportSize(256, 192);
/// Below this share of agreeing pixels, a frame does not show the content it is compared with.
constexpr double kOtherContentAgreement = 0.99;

QString ownerName(ContentOwner owner)
{
    const std::string_view name = render::contentOwnerName(owner);
    return QString::fromUtf8(name.data(), qsizetype(name.size()));
}

/// Whether the last frame shows `owner`'s pose at `positions` — the content's owner, its
/// shown scene, the frame against the reference — and no longer `before`: nullopt, or
/// what is wrong.
std::optional<QString> shownProblem(MainWindow& window, ContentOwner owner, const std::vector<glm::vec3>& positions,
                                    const std::vector<glm::vec3>& before, const QString& name)
{
    const render::ShownContent& content = *window.viewport()->content();
    if (content.poseOwner() != owner)
        return QStringLiteral("%1: the pose shown is the %2's, not the %3's")
            .arg(name, ownerName(content.poseOwner()), ownerName(owner));
    if (content.posedScene()->objects.front().mesh.positions != positions)
        return QStringLiteral("%1: the shown scene does not hold the %2's positions").arg(name, ownerName(owner));
    if (std::optional<QString> problem = test::posedFrameDisagreement(window, positions, name))
        return problem;
    const double stale = test::posedFrameAgainstReference(window, before).comparison.agreement();
    qInfo("%s: %.4f of the compared pixels agree with the content shown before", qPrintable(name), stale);
    if (stale > kOtherContentAgreement)
        return QStringLiteral("%1: the frame agrees with the content shown before as well (%2)").arg(name).arg(stale);
    return std::nullopt;
}

/// The vertices `pose` moves further than `distance` from `rest`.
std::size_t movedVertices(const std::vector<glm::vec3>& pose, const std::vector<glm::vec3>& rest, float distance)
{
    std::size_t moved = 0;
    for (std::size_t v = 0; v < pose.size(); ++v)
        moved += glm::distance(pose[v], rest[v]) > distance ? 1 : 0;
    return moved;
}

} // namespace

class TestShownFrames : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void eachFrameShowsItsOwnersContent();

private:
    /// Runs the Skeleton panel (20 joints) on the star shown; false when it did not finish.
    [[nodiscard]] static bool extractSkeleton(MainWindow& window);
    /// The bone whose turn about the view axis moves the most vertices (the pose is reset after).
    [[nodiscard]] static int boneMovingMost(SkeletonPanel& panel, const std::vector<glm::vec3>& rest);

    QTemporaryDir m_dir;
    QString m_star;
    QString m_balls;
};

void TestShownFrames::initTestCase()
{
    TRIMLAB_INIT_WIDGET_TEST();
    QVERIFY(m_dir.isValid());
    m_star = m_dir.filePath(QStringLiteral("star.obj"));
    QVERIFY(test::writePlainObj(test::Star{}.mesh(0.07), m_star));
    m_balls = m_dir.filePath(QStringLiteral("meeting-balls"));
    QVERIFY(test::writeMeetingBalls(m_balls));
}

bool TestShownFrames::extractSkeleton(MainWindow& window)
{
    child<QDockWidget>(&window, "skeletonDock")->raise();
    SkeletonPanel* panel = window.skeletonWorkspace()->panel();
    child<QSpinBox>(panel, "skeletonNodesSpinBox")->setValue(20);
    QSignalSpy finished(panel->task(), &BackgroundJobBase::finished);
    QTest::mouseClick(child<QPushButton>(panel, "runSkeletonButton"), Qt::LeftButton);
    return QTest::qWaitFor([&] { return !finished.isEmpty(); }, kWaitMs) && panel->result();
}

int TestShownFrames::boneMovingMost(SkeletonPanel& panel, const std::vector<glm::vec3>& rest)
{
    int best = -1;
    std::size_t most = 0;
    for (int bone = 0; bone < int(panel.result()->rig.bones.size()); ++bone) {
        panel.rotateBone(bone, glm::dvec3(0.0, 0.0, 1.0), glm::radians(50.0));
        const std::size_t moved = movedVertices(panel.shownPositions(), rest, 0.05f);
        if (moved > most) {
            most = moved;
            best = bone;
        }
        panel.resetPose();
    }
    return best;
}

void TestShownFrames::eachFrameShowsItsOwnersContent()
{
    test::MessageBoxCloser closer;
    auto window = test::showDesignWindow(m_dir.filePath(QStringLiteral("shown.ini")), kViewportSize);
    QVERIFY(test::openDesignAndWait(*window, m_star));
    ViewportWidget* viewport = window->viewport();
    const render::ShownContent& content = *viewport->content();
    const std::vector<glm::vec3> rest = window->scene()->scene.objects.front().mesh.positions;
    QCOMPARE(content.poseOwner(), ContentOwner::DesignHistory);

    // The skeleton poses the star.
    QVERIFY(extractSkeleton(*window));
    SkeletonPanel* skeleton = window->skeletonWorkspace()->panel();
    const int bone = boneMovingMost(*skeleton, rest);
    QVERIFY(bone >= 0);
    QVERIFY(test::waitForFrameAfter(
        *window, [&] { skeleton->rotateBone(bone, glm::dvec3(0.0, 0.0, 1.0), glm::radians(50.0)); }, kWaitMs));
    test::waitUntilViewIdle(*viewport);
    const std::vector<glm::vec3> skeletonPose = skeleton->shownPositions();
    qInfo("bone %d turned: %zu of %zu vertices moved", bone, movedVertices(skeletonPose, rest, 0.05f), rest.size());
    if (const auto problem = shownProblem(*window, ContentOwner::Skeleton, skeletonPose, rest, "skeleton"))
        QFAIL(qPrintable(*problem));

    // A brush stroke: the design history's new frame replaces the skeleton's pose.
    window->designWorkspace()->brushAction()->setChecked(true);
    QVERIFY(test::strokeAtCentre(*window, QPoint(30, -20)));
    window->designWorkspace()->brushAction()->setChecked(false);
    test::waitUntilViewIdle(*viewport);
    const DesignSession* session = window->designWorkspace()->session();
    const std::vector<glm::vec3> stroked = session->shownPositions();
    QVERIFY(movedVertices(stroked, rest, 0.05f) > 0);
    if (const auto problem = shownProblem(*window, ContentOwner::DesignHistory, stroked, skeletonPose, "stroke"))
        QFAIL(qPrintable(*problem));

    // Another frame of the history: the base mesh.
    QVERIFY(test::waitForFrameAfter(
        *window, [&] { window->designWorkspace()->showFrame(0); }, kWaitMs));
    test::waitUntilViewIdle(*viewport);
    if (const auto problem = shownProblem(*window, ContentOwner::DesignHistory, rest, stroked, "frame-0"))
        QFAIL(qPrintable(*problem));

    // The skeleton again, then the same pose under the dynamic rules: the history's chain
    // ends in the skeleton's pose, deforming the current set's reference into it.
    QVERIFY(test::waitForFrameAfter(
        *window, [&] { skeleton->rotateBone(bone, glm::dvec3(0.0, 0.0, 1.0), glm::radians(-20.0)); }, kWaitMs));
    test::waitUntilViewIdle(*viewport);
    const std::vector<glm::vec3> posedAgain = skeleton->shownPositions();
    if (const auto problem = shownProblem(*window, ContentOwner::Skeleton, posedAgain, rest, "skeleton-again"))
        QFAIL(qPrintable(*problem));
    auto* classification = child<QComboBox>(window.get(), "classificationComboBox");
    QVERIFY(test::waitForFrameAfter(
        *window, [&] { classification->setCurrentIndex(1); }, kWaitMs));
    QVERIFY(QTest::qWaitFor([&] { return viewport->lastDynamicStats().has_value(); }, kWaitMs));
    test::waitUntilViewIdle(*viewport);
    QCOMPARE(content.poseOwner(), ContentOwner::Skeleton);
    QCOMPARE(content.chainOwner(), ContentOwner::DesignHistory);
    const timeline::Timeline& history = session->timeline();
    const int shownFrame = session->shownFrame();
    DynamicChain expected =
        dynamicChainTo(history, shownFrame, viewport->lastFrame()->settings.rule, session->modelMatrix());
    const timeline::Timeline::ChainLink link = history.chainTo(shownFrame).back();
    expected.levels.back() = dynamicShownLevel(history, history.positionsAt(link.referenceFrame), posedAgain, link.rule,
                                               session->modelMatrix());
    if (const auto problem =
            test::frameDisagreement(test::chainFrameAgainstReference(*window, expected), "skeleton-dynamic"))
        QFAIL(qPrintable(*problem));
    QVERIFY(test::waitForFrameAfter(
        *window, [&] { classification->setCurrentIndex(0); }, kWaitMs));

    // An animation plays: its poses are shown, nothing of the star's features is left.
    window->designWorkspace()->undoAction()->trigger(); // the history unchanged: no prompt to save it
    QSignalSpy loaded(window.get(), &MainWindow::animationLoaded);
    window->openAnimation(m_balls);
    QVERIFY(QTest::qWaitFor([&] { return !loaded.isEmpty() && !window->isLoading(); }, kWaitMs));
    QVERIFY(QTest::qWaitFor([&] { return viewport->lastFrame().has_value(); }, kWaitMs));
    QVERIFY(!window->designWorkspace()->session());
    const std::vector<std::vector<glm::vec3>>& poses = window->animation()->animation->poses;
    auto* slider = child<QSlider>(window.get(), "poseSlider");
    slider->setFocus();
    QVERIFY(test::waitForFrameAfter(
        *window, [&] { QTest::keyClick(slider, Qt::Key_End); }, kWaitMs));
    test::waitUntilViewIdle(*viewport);
    QCOMPARE(content.colorOwner(), ContentOwner::None);
    QCOMPARE(content.chainOwner(), ContentOwner::None);
    if (const auto problem =
            shownProblem(*window, ContentOwner::AnimationPlayback, poses.back(), poses.front(), "animation"))
        QFAIL(qPrintable(*problem));
    QVERIFY2(closer.seen().isEmpty(), qPrintable(closer.seen().join(QLatin1Char('|'))));
}

QTEST_MAIN(TestShownFrames)
#include "tst_shown_frames.moc"
