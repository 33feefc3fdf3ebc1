// Mesh animations in the real main window, driven like a user: open through
// MainWindow::openAnimation() (the path the menu, recent list and drops take), step and
// play the Timeline with keys and clicks and check every shown pose against the exact CPU
// reference, then segment with the Segmentation panel — Run, Cancel, the h slider, the
// three modes, color by segment, export — and compare what it shows with the core run
// directly. Settings go to INI files in a temporary folder, never the user's.
#include "gl_test_context.h"
#include "held_background_job.h"
#include "image_artifacts.h"
#include "meeting_balls.h"
#include "message_box_closer.h"
#include "named_child.h"
#include "plain_obj.h"
#include "shown_main_window.h"
#include "widget_test_main.h"
#include "posed_frame_check.h"
#include "test_paths.h"
#include "trim_comparison.h"

#include "core/animation/animation_chain.h"
#include "core/animation/animation_loader.h"
#include "core/animation/animation_segmenter.h"
#include "core/animation/segment_coloring.h"
#include "ui/animation/animation_opener.h"
#include "ui/common/background_job.h"
#include "ui/common/loaded_animation.h"
#include "ui/window/main_window.h"
#include "ui/render_panel/render_workspace.h"
#include "ui/animation/animation_workspace.h"
#include "ui/animation/pose_history_bar.h"
#include "core/mesh/mesh_io.h"
#include "core/scene/shape_generators.h"
#include "core/view/camera.h"
#include "ui/render_panel/render_panel.h"
#include "ui/animation/segment_stream.h"
#include "ui/animation/segmentation_panel.h"
#include "ui/animation/timeline_panel.h"
#include "core/trim/dynamic_reference_renderer.h"
#include "core/trim/reference_renderer.h"
#include "core/trim/trim_shading.h"
#include "ui/viewport/viewport_widget.h"

#include "render/shown_content.h"

#include <QtTest>

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QMimeData>
#include <QProgressDialog>
#include <QThread>
#include <QElapsedTimer>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QThreadPool>
#include <QStatusBar>
#include <QToolButton>

#include <cmath>
#include <filesystem>
#include <map>
#include <tuple>
#include <set>

using namespace trimlab;
using namespace trimlab::ui;
using trimlab::test::child;
using trimlab::test::MessageBoxCloser;

namespace {

constexpr QSize kViewportSize(256, 192);
constexpr int kWaitMs = 20000;

QString testAnimation(const char* name)
{
    return QString::fromStdString(test::testDataPath(std::string("animations/") + name).string());
}

QString walkingCat()
{
    return QString::fromStdString(test::sharedDataPath("anim/walking-cat").string());
}

/// Types `value` into a spin box as a user would and confirms with Return.
void typeInto(QSpinBox* box, int value)
{
    QTest::keyClick(box, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(box, QString::number(value));
    QTest::keyClick(box, Qt::Key_Return);
}

/// The hue in degrees of an 8-bit color, or nullopt when its chroma (max − min channel)
/// is below `minChroma` levels and the hue therefore too coarse to compare.
std::optional<double> hueOf(const QColor& color, int minChroma)
{
    const int high = std::max({color.red(), color.green(), color.blue()});
    const int low = std::min({color.red(), color.green(), color.blue()});
    if (high - low < minChroma)
        return std::nullopt;
    return color.hsvHueF() * 360.0;
}

double hueDistanceDegrees(double a, double b)
{
    const double d = std::fmod(std::abs(a - b), 360.0);
    return std::min(d, 360.0 - d);
}

/// The reference segmentation of the walking cat for the panel's default choices,
/// computed directly with the core (loaded once).
const AnimationSegmenter& referenceCat()
{
    static const AnimationSegmenter segmenter = [] {
        AnimationSegmenter s(loadAnimation(walkingCat().toStdString()), SegmentationChoices{}.segmenterSettings());
        s.run();
        return s;
    }();
    return segmenter;
}

} // namespace

class TestAnimationPanel : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void timelineShowsEveryPoseLikeTheReference();
    void fitFramesEveryPose();
    void playbackAndGltfAndDrop();
    void playbackKeepsTimeOnASlowView();
    void dynamicRuleCarriesTheClassificationFromPoseToPose();
    void closeHolesPlaysAnOpenAnimationTrimmed();
    void skinnedGltfPlaysOnTheGpu();
    void brokenAnimationNamesTheFile();
    void cancelOpeningKeepsTheScene();
    void runAndHSliderFollowTheCore();
    void colorBySegmentShowsSegmentColors();
    void cancelKeepsThePreviousResult();
    void realTimeStreamEqualsTheGlobalRun();
    void variableModeShowsEachPose();
    void exportWritesJsonCsvAndGltf();
    void choicesPersist();
    void screenshot();

private:
    [[nodiscard]] std::unique_ptr<MainWindow> showWindow(const QString& settingsName, QSize viewport = kViewportSize);
    [[nodiscard]] static bool openAndWait(MainWindow& window, const QString& source);
    [[nodiscard]] std::unique_ptr<MainWindow> segmentedCat(const QString& settingsName, QSize viewport = kViewportSize);
    [[nodiscard]] static bool waitForNewFrame(MainWindow& window, const std::function<void()>& action);
    [[nodiscard]] static std::optional<QString> poseDisagreement(MainWindow& window, int pose);
    [[nodiscard]] static std::optional<QString> dynamicPoseDisagreement(MainWindow& window, int pose,
                                                                        PoseReference reference, DynamicRule rule);

    QTemporaryDir m_dir;
};

void TestAnimationPanel::initTestCase()
{
    TRIMLAB_INIT_WIDGET_TEST();
    QVERIFY(m_dir.isValid());
}

std::unique_ptr<MainWindow> TestAnimationPanel::showWindow(const QString& settingsName, QSize viewport)
{
    return test::showMainWindow(m_dir.filePath(settingsName + QStringLiteral(".ini")), viewport);
}

bool TestAnimationPanel::openAndWait(MainWindow& window, const QString& source)
{
    QSignalSpy loaded(&window, &MainWindow::animationLoaded);
    window.openAnimation(source);
    return QTest::qWaitFor([&] { return !loaded.isEmpty() && !window.isLoading(); }, kWaitMs) &&
           loaded.front().at(0).toString() == source &&
           QTest::qWaitFor([&] { return window.viewport()->lastFrame().has_value(); }, kWaitMs);
}

// The walking cat opened and segmented by clicking Run with the default choices.
std::unique_ptr<MainWindow> TestAnimationPanel::segmentedCat(const QString& settingsName, QSize viewport)
{
    auto window = showWindow(settingsName, viewport);
    if (!openAndWait(*window, walkingCat()))
        return nullptr;
    SegmentationPanel* panel = window->animationWorkspace()->segmentationPanel();
    QTest::mouseClick(child<QPushButton>(panel, "runSegmentationButton"), Qt::LeftButton);
    if (!QTest::qWaitFor([&] { return panel->result() && !panel->isRunning(); }, kWaitMs))
        return nullptr;
    return window;
}

// Runs `action` and waits for a frame rendered after it.
bool TestAnimationPanel::waitForNewFrame(MainWindow& window, const std::function<void()>& action)
{
    return test::waitForFrameAfter(window, action, kWaitMs);
}

// The viewport's last frame against the CPU reference of the scene at pose `pose`
// (posed_frame_check.h); the frame's picture is kept in the test output either way.
std::optional<QString> TestAnimationPanel::poseDisagreement(MainWindow& window, int pose)
{
    const QString name = QStringLiteral("animation-pose-%1").arg(pose);
    const std::filesystem::path picture = test::outputDir() / (name + QStringLiteral(".png")).toStdString();
    window.viewport()->readColorImage().save(QString::fromStdString(picture.string()));
    return test::posedFrameDisagreement(window, window.animation()->animation->poses[std::size_t(pose)], name);
}

// The viewport's last frame against the exact dynamic reference of the animation's chain
// for `pose` (core/animation/animation_chain.h), the frame's camera, size and settings
// (whose static rule classifies the rest pose).
std::optional<QString> TestAnimationPanel::dynamicPoseDisagreement(MainWindow& window, int pose,
                                                                   PoseReference reference, DynamicRule rule)
{
    const QString name = QStringLiteral("animation-dynamic-%1-pose-%2")
                             .arg(QString::fromLatin1(poseReferenceName(reference).data()))
                             .arg(pose);
    const ViewportFrame frame = *window.viewport()->lastFrame();
    const std::optional<DynamicChain> chain =
        animationChain(*window.animation()->animation, std::size_t(pose), reference, rule, frame.settings.rule);
    if (!chain)
        return name + QStringLiteral(": the rest pose has no chain");
    return test::frameDisagreement(test::chainFrameAgainstReference(window, *chain), name);
}

// horse-gallop opens with the trim controls off: every pose has two holes, of 19 edges in all. Edit ▸
// Close Holes closes it in every pose, the trim modes become available, and the timeline
// plays it trimmed: under the confluent rule against the previous pose, each pose stepped
// to agrees with the exact dynamic reference of the closed animation's chain, and Play
// advances through trimmed poses. A closed animation leaves the action off.
void TestAnimationPanel::closeHolesPlaysAnOpenAnimationTrimmed()
{
    const QString horse = QString::fromStdString(test::sharedDataPath("anim/horse-gallop").string());
    if (!QFileInfo::exists(horse))
        QSKIP("../shared/data/anim/horse-gallop is not here");
    auto window = showWindow(QStringLiteral("close-holes"));
    QVERIFY(openAndWait(*window, horse));
    auto* closeHoles = child<QAction>(window.get(), "closeHolesAction");
    QVERIFY(closeHoles->isEnabled());
    QVERIFY(!window->scene()->trimmable());
    QVERIFY(!window->viewport()->lastFrame()->settings.trimEnabled);
    const std::size_t openTriangles = window->animation()->animation->triangleCount();

    QSignalSpy loaded(window.get(), &MainWindow::animationLoaded);
    QVERIFY(waitForNewFrame(*window, [&] { closeHoles->trigger(); }));
    QCOMPARE(loaded.size(), 1);
    QVERIFY2(window->scene()->trimmable(), window->scene()->trimUnavailableReason().c_str());
    QCOMPARE(window->animation()->animation->triangleCount(), openTriangles + 19);
    QVERIFY(!closeHoles->isEnabled());
    QVERIFY(window->viewport()->lastFrame()->settings.trimEnabled);
    QVERIFY2(window->statusBar()->currentMessage().contains(QStringLiteral("closed 2 holes of 19 edges")),
             qPrintable(window->statusBar()->currentMessage()));

    auto* rule = child<QComboBox>(window.get(), "poseRuleCombo");
    QVERIFY(waitForNewFrame(*window, [&] { rule->setCurrentIndex(rule->findData(int(DynamicRule::Confluent))); }));
    QCOMPARE(window->animationWorkspace()->poseHistoryBar()->choices().reference, PoseReference::Previous);
    auto* slider = child<QSlider>(window.get(), "poseSlider");
    slider->setFocus();
    for (int pose : {1, 2}) {
        QVERIFY(waitForNewFrame(*window, [&] { QTest::keyClick(slider, Qt::Key_Right); }));
        QCOMPARE(window->animationWorkspace()->timelinePanel()->pose(), pose);
        if (const auto problem =
                dynamicPoseDisagreement(*window, pose, PoseReference::Previous, DynamicRule::Confluent))
            QFAIL(qPrintable(*problem));
    }

    TimelinePanel* timeline = window->animationWorkspace()->timelinePanel();
    QSignalSpy poses(timeline, &TimelinePanel::poseChanged);
    auto* play = child<QToolButton>(window.get(), "playButton");
    QTest::mouseClick(play, Qt::LeftButton);
    QVERIFY(QTest::qWaitFor([&] { return poses.count() >= 2; }, kWaitMs));
    QTest::mouseClick(play, Qt::LeftButton);
    QVERIFY(!timeline->isPlaying());
    const int played = timeline->pose();
    QVERIFY(played > 2);
    slider->setFocus();
    QVERIFY(waitForNewFrame(*window, [&] { QTest::keyClick(slider, Qt::Key_Right); }));
    QCOMPARE(timeline->pose(), played + 1);
    QVERIFY(window->viewport()->lastFrame()->settings.trimEnabled);
    QCOMPARE(window->viewport()->lastDynamicStats().value().levels, played + 1);

    QVERIFY(openAndWait(*window, testAnimation("folding_box")));
    QVERIFY(!closeHoles->isEnabled());
}

// The folding box (three poses of a closed tube, the last one folded through itself): the
// rest pose becomes the scene and is trimmed like a mesh; every pose the keyboard steps
// to changes the framebuffer and agrees with the reference ray caster on that pose. The
// bar (an open strip) leaves the trim controls off and says why.
void TestAnimationPanel::timelineShowsEveryPoseLikeTheReference()
{
    auto window = showWindow(QStringLiteral("timeline"));
    const QString box = testAnimation("folding_box");
    QVERIFY(openAndWait(*window, box));
    const MeshAnimation& animation = *window->animation()->animation;
    QCOMPARE(animation.poseCount(), std::size_t(3));
    QCOMPARE(window->scene()->scene.objects.size(), std::size_t(1));
    QCOMPARE(window->scene()->scene.objects.front().mesh.positions, animation.poses.front());
    QVERIFY(window->findChild<QDockWidget*>(QStringLiteral("timelineDock"))->isVisible());
    QVERIFY(window->scene()->trimmable());
    QVERIFY(window->viewport()->lastFrame()->settings.trimEnabled);
    QVERIFY(window->recentAnimations().contains(QFileInfo(box).absoluteFilePath()));

    auto* slider = child<QSlider>(window.get(), "poseSlider");
    auto* label = child<QLabel>(window.get(), "poseLabel");
    QCOMPARE(slider->maximum(), 2);
    QVERIFY2(label->text().contains(QStringLiteral("pose_0.obj")), qPrintable(label->text()));
    if (const auto problem = poseDisagreement(*window, 0))
        QFAIL(qPrintable(*problem));
    QImage previous = window->viewport()->readColorImage();
    slider->setFocus();
    using Step = std::tuple<Qt::Key, int, const char*>; // key, pose it leads to, that pose's file
    const Step steps[] = {{Qt::Key_Right, 1, "pose_1.obj"}, {Qt::Key_End, 2, "pose_2.obj"}};
    for (const auto& [key, pose, name] : steps) {
        QVERIFY(waitForNewFrame(*window, [&] { QTest::keyClick(slider, key); }));
        QCOMPARE(window->animationWorkspace()->timelinePanel()->pose(), pose);
        QVERIFY2(label->text().contains(QString::fromLatin1(name)), qPrintable(label->text()));
        const QImage shown = window->viewport()->readColorImage();
        int changed = 0;
        for (int y = 0; y < shown.height(); ++y)
            for (int x = 0; x < shown.width(); ++x)
                changed += shown.pixel(x, y) != previous.pixel(x, y) ? 1 : 0;
        QVERIFY2(changed > 200, qPrintable(QStringLiteral("pose %1: only %2 pixels changed").arg(pose).arg(changed)));
        if (const auto problem = poseDisagreement(*window, pose))
            QFAIL(qPrintable(*problem));
        previous = shown;
    }

    QVERIFY(openAndWait(*window, testAnimation("bar")));
    QVERIFY(!child<QCheckBox>(window.get(), "trimCheckBox")->isEnabled());
    auto* reason = child<QLabel>(window.get(), "trimUnavailableLabel");
    QVERIFY(reason->isVisible());
    QVERIFY2(reason->text().contains(QString::fromStdString(window->scene()->trimUnavailableReason())),
             qPrintable(reason->text()));
    QVERIFY(!window->viewport()->lastFrame()->settings.trimEnabled);
    QCOMPARE(slider->value(), 0); // a new animation starts at its first pose
}

// Two balls that move into each other (meeting_balls.h), cut open by the Render panel's
// first clip plane, played as a deformation history: under the confluent rule against the
// previous pose, stepping forward appends one set per pose and characterizes only it (the
// classification carried from pose to pose), and every pose agrees with the exact
// dynamic reference of its whole chain; scrubbing back and jumping to the same pose
// builds the chain again and shows the same picture. The history matters: where the
// balls overlap, parity alone carves the lens out and the confluent rule keeps it solid.
// Against the rest pose every pose is one set. The rest pose itself is shown by the
// static rule.
void TestAnimationPanel::dynamicRuleCarriesTheClassificationFromPoseToPose()
{
    const QString balls = m_dir.filePath(QStringLiteral("meeting-balls"));
    QVERIFY(test::writeMeetingBalls(balls));
    auto window = showWindow(QStringLiteral("dynamic-timeline"));
    QVERIFY(openAndWait(*window, balls));
    QVERIFY(waitForNewFrame(*window,
                            [&] { QTest::keyClick(child<QComboBox>(window.get(), "ruleComboBox"), Qt::Key_Home); }));
    QCOMPARE(window->viewport()->lastFrame()->settings.rule, StaticRule::Parity);
    QVERIFY(waitForNewFrame(
        *window, [&] { QTest::mouseClick(child<QCheckBox>(window.get(), "clipPlaneEnabled0"), Qt::LeftButton); }));
    QVERIFY(window->viewport()->lastFrame()->settings.clipSet().anyEnabled());

    auto* slider = child<QSlider>(window.get(), "poseSlider");
    slider->setFocus();
    QVERIFY(waitForNewFrame(*window, [&] { QTest::keyClick(slider, Qt::Key_End); }));
    const TrimImage parity = window->viewport()->readTrimImage();
    QVERIFY(waitForNewFrame(*window, [&] { QTest::keyClick(slider, Qt::Key_Home); }));

    auto* rule = child<QComboBox>(window.get(), "poseRuleCombo");
    auto* reference = child<QComboBox>(window.get(), "poseReferenceCombo");
    QVERIFY(!reference->isEnabled()); // the static rule has no reference
    QVERIFY(waitForNewFrame(*window, [&] { rule->setCurrentIndex(rule->findData(int(DynamicRule::Confluent))); }));
    QVERIFY(reference->isEnabled());
    QCOMPARE(window->animationWorkspace()->poseHistoryBar()->choices().reference, PoseReference::Previous);
    QVERIFY(!window->viewport()->lastDynamicStats()); // pose 0, the rest pose: static
    if (const auto problem = poseDisagreement(*window, 0))
        QFAIL(qPrintable(*problem));

    slider->setFocus();
    for (int pose : {1, 2}) {
        QVERIFY(waitForNewFrame(*window, [&] { QTest::keyClick(slider, Qt::Key_Right); }));
        QCOMPARE(window->animationWorkspace()->timelinePanel()->pose(), pose);
        const render::DynamicFrameStats stats = window->viewport()->lastDynamicStats().value();
        QCOMPARE(stats.levels, pose);
        QCOMPARE(stats.characterizedLevels, pose - 1); // pose 2: only the set appended
        if (const auto problem =
                dynamicPoseDisagreement(*window, pose, PoseReference::Previous, DynamicRule::Confluent))
            QFAIL(qPrintable(*problem));
    }
    const TrimImage played = window->viewport()->readTrimImage();
    QVERIFY(child<QLabel>(window.get(), "poseHistoryStatus")->text().contains(QStringLiteral("2 sets")));
    const TrimImage playedMeshIds = withMeshIds(played, window->viewport()->content()->chain()->shownLevel().frame);
    int differing = 0;
    for (std::size_t i = 0; i < played.pixels.size(); ++i)
        differing += playedMeshIds.pixels[i].primitiveId != parity.pixels[i].primitiveId ? 1 : 0;
    qInfo("%d pixels differ from parity alone", differing);
    QVERIFY2(differing > 100, qPrintable(QString::number(differing)));

    QVERIFY(waitForNewFrame(*window, [&] { QTest::keyClick(slider, Qt::Key_Home); }));
    QVERIFY(!window->viewport()->lastDynamicStats());
    QVERIFY(waitForNewFrame(*window, [&] { QTest::keyClick(slider, Qt::Key_End); }));
    QCOMPARE(window->viewport()->lastDynamicStats()->characterizedLevels, 1); // the whole chain, from the rest pose
    const TrimImage jumped = window->viewport()->readTrimImage();
    QCOMPARE(jumped.pixels.size(), played.pixels.size());
    for (std::size_t i = 0; i < played.pixels.size(); ++i) {
        QCOMPARE(jumped.pixels[i].objectId, played.pixels[i].objectId);
        QCOMPARE(jumped.pixels[i].primitiveId, played.pixels[i].primitiveId);
    }

    QVERIFY(
        waitForNewFrame(*window, [&] { reference->setCurrentIndex(reference->findData(int(PoseReference::Rest))); }));
    QCOMPARE(window->viewport()->lastDynamicStats()->levels, 1);
    if (const auto problem = dynamicPoseDisagreement(*window, 2, PoseReference::Rest, DynamicRule::Confluent))
        QFAIL(qPrintable(*problem));

    QVERIFY(waitForNewFrame(*window, [&] { rule->setCurrentIndex(rule->findData(-1)); })); // static again
    QVERIFY(!window->viewport()->lastDynamicStats());
    if (const auto problem = poseDisagreement(*window, 2))
        QFAIL(qPrintable(*problem));
}

// A skinned glTF file plays from its own skin on the GPU (core/skinning/file_skin_model.h
// into the viewport's GPU skinning): every pose's frame is skinned on the GPU and agrees
// with the reference ray caster on the pose the loader sampled on the CPU.
void TestAnimationPanel::skinnedGltfPlaysOnTheGpu()
{
    auto window = showWindow(QStringLiteral("skinned-gltf"));
    QVERIFY(openAndWait(*window, testAnimation("skinned_bar.gltf")));
    QVERIFY(window->animation()->fileSkin);
    auto* slider = child<QSlider>(window.get(), "poseSlider");
    slider->setFocus();
    QCOMPARE(slider->maximum(), 1);
    QVERIFY(waitForNewFrame(*window, [&] { QTest::keyClick(slider, Qt::Key_End); }));
    QCOMPARE(window->viewport()->poseEvaluation(), render::PoseEvaluation::GpuSkinning);
    if (const auto problem = poseDisagreement(*window, 1))
        QFAIL(qPrintable(*problem));
    QVERIFY(waitForNewFrame(*window, [&] { QTest::keyClick(slider, Qt::Key_Home); }));
    QCOMPARE(window->viewport()->poseEvaluation(), render::PoseEvaluation::GpuSkinning);
    if (const auto problem = poseDisagreement(*window, 0))
        QFAIL(qPrintable(*problem));
}

// A box that travels 6 units along x over three poses: the view opened on it, and Fit
// (F) at its first pose, frame every pose, so the box never leaves the picture as it
// plays.
void TestAnimationPanel::fitFramesEveryPose()
{
    const QString folder = m_dir.filePath(QStringLiteral("travelling_box"));
    QVERIFY(QDir().mkpath(folder));
    for (int pose = 0; pose < 3; ++pose) {
        const double x = 3.0 * pose;
        const TriangleMesh box = makeBox({x - 0.5, -0.5, -0.5}, {x + 0.5, 0.5, 0.5});
        QVERIFY(test::writePlainObj(box, folder + QStringLiteral("/pose_%1.obj").arg(pose)));
    }
    auto window = showWindow(QStringLiteral("fit-motion"));
    QVERIFY(openAndWait(*window, folder));
    const MeshAnimation& animation = *window->animation()->animation;
    QCOMPARE(animation.poseCount(), std::size_t(3));
    const auto everyPoseInView = [&](const Camera& camera) {
        const QSize size = window->viewport()->framePixelSize();
        const glm::dmat4 clip = projectionMatrix(camera, double(size.width()) / size.height()) * viewMatrix(camera);
        for (const auto& pose : animation.poses)
            for (const glm::vec3& p : pose) {
                const glm::dvec4 c = clip * glm::dvec4(glm::dvec3(p), 1.0);
                if (c.w <= 0.0 || std::abs(c.x) > c.w || std::abs(c.y) > c.w)
                    return false;
            }
        return true;
    };
    QVERIFY(everyPoseInView(window->viewport()->camera()));
    window->viewport()->setCamera(Camera{{0.0, 0.0, 1.5}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 45.0});
    QVERIFY(!everyPoseInView(window->viewport()->camera())); // close up: the case arises
    window->viewport()->setFocus();
    QVERIFY(waitForNewFrame(*window, [&] { QTest::keyClick(window->viewport(), Qt::Key_F); }));
    QCOMPARE(window->animationWorkspace()->timelinePanel()->pose(), 0);
    QVERIFY(everyPoseInView(window->viewport()->camera()));
}

// Play advances the poses on a timer and pauses again; a glTF animation opens through the
// same entry point; a folder dropped on the window opens as an animation.
void TestAnimationPanel::playbackAndGltfAndDrop()
{
    auto window = showWindow(QStringLiteral("playback"));
    QVERIFY(openAndWait(*window, testAnimation("skinned_bar.gltf")));
    QVERIFY(window->animation()->animation->poseCount() > 1);
    TimelinePanel* timeline = window->animationWorkspace()->timelinePanel();
    QSignalSpy poses(timeline, &TimelinePanel::poseChanged);
    auto* play = child<QToolButton>(window.get(), "playButton");
    QTest::mouseClick(play, Qt::LeftButton);
    QVERIFY(timeline->isPlaying());
    QVERIFY(QTest::qWaitFor([&] { return poses.count() >= 2; }, kWaitMs));
    QTest::mouseClick(play, Qt::LeftButton);
    QVERIFY(!timeline->isPlaying());

    QMimeData mime;
    const QString bar = testAnimation("bar");
    mime.setUrls({QUrl::fromLocalFile(bar)});
    QSignalSpy loaded(window.get(), &MainWindow::animationLoaded);
    QDragEnterEvent enter(QPoint(20, 20), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(window.get(), &enter);
    QDropEvent drop(QPointF(20.0, 20.0), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(window.get(), &drop);
    QVERIFY(QTest::qWaitFor([&] { return !loaded.isEmpty(); }, kWaitMs));
    QCOMPARE(window->animation()->animation->poseCount(), std::size_t(3));
    QCOMPARE(timeline->pose(), 0);
}

// A view that takes 100 ms per pose (the UI thread held in the pose slot, like a slow
// renderer) cannot show 24 poses a second: playback drops poses and keeps time, and the
// rate label says how many it showed. It advanced one pose per tick, about 7 a second.
void TestAnimationPanel::playbackKeepsTimeOnASlowView()
{
    if (!QFileInfo::exists(walkingCat()))
        QSKIP("../shared/data/anim/walking-cat is missing");
    auto window = showWindow(QStringLiteral("slow-playback"));
    QVERIFY(openAndWait(*window, walkingCat()));
    TimelinePanel* timeline = window->animationWorkspace()->timelinePanel();
    timeline->setPlaybackChoices(24, false);
    QElapsedTimer clock;
    std::vector<std::pair<qint64, int>> shown; // (ms since Play was pressed, pose) per pose change
    const QMetaObject::Connection slow = connect(timeline, &TimelinePanel::poseChanged, this, [&](int pose) {
        shown.emplace_back(clock.elapsed(), pose);
        QThread::msleep(100);
    });
    clock.start();
    QTest::mouseClick(child<QToolButton>(window.get(), "playButton"), Qt::LeftButton);
    QTest::qWait(1200);
    timeline->pause();
    disconnect(slow);
    QVERIFY(shown.size() >= 3);
    // Each pose shown is the one the clock had reached (Play started the clock a moment
    // after `clock`, so the pose may lag it by one); one pose per tick lags further and
    // further behind.
    const auto [lastMs, lastPose] = shown.back();
    qInfo("%zu poses shown in %lld ms at 24 fps; the last was pose %d of %d", shown.size(), lastMs, lastPose,
          timeline->poseCount() - 1);
    const int expected = std::min(timeline->poseCount() - 1, int(24 * lastMs / 1000));
    QVERIFY2(lastPose >= expected - 1, qPrintable(QStringLiteral("pose %1, expected %2").arg(lastPose).arg(expected)));
    auto* rate = child<QLabel>(window.get(), "playbackRateLabel");
    QVERIFY(rate);
    qInfo("rate label: %s", qPrintable(rate->text()));
    QVERIFY2(rate->text().contains(QStringLiteral("fps shown")), qPrintable(rate->text()));
    QVERIFY(timeline->achievedFps() > 0.0 && timeline->achievedFps() < 12.0);
}

// Poses that disagree: a dialog names the offending file; the open animation stays.
void TestAnimationPanel::brokenAnimationNamesTheFile()
{
    auto window = showWindow(QStringLiteral("broken"));
    const QString bar = testAnimation("bar");
    QVERIFY(openAndWait(*window, bar));
    MessageBoxCloser closer;
    QSignalSpy failed(window.get(), &MainWindow::sceneLoadFailed);
    const QString broken = testAnimation("mismatched_vertices");
    window->openAnimation(broken);
    QVERIFY(failed.wait(kWaitMs));
    QCOMPARE(failed.front().at(0).toString(), broken);
    QVERIFY(QTest::qWaitFor([&] { return !closer.seen().isEmpty(); }, kWaitMs));
    const QString shown = closer.seen().front();
    QVERIFY2(shown.contains(QStringLiteral("mesh_0001.obj")), qPrintable(shown));
    QVERIFY2(shown.contains(QStringLiteral("mismatched_vertices")), qPrintable(shown));
    QCOMPARE(QString::fromStdString(window->scene()->source), bar);
    QCOMPARE(window->animation()->animation->poseCount(), std::size_t(3));
    QVERIFY(!window->recentAnimations().contains(QFileInfo(broken).absoluteFilePath()));
}

// The progress dialog's Cancel stops the loader and keeps what was shown.
void TestAnimationPanel::cancelOpeningKeepsTheScene()
{
    auto window = showWindow(QStringLiteral("cancel-open"));
    const QString bar = testAnimation("bar");
    QVERIFY(openAndWait(*window, bar));
    QSignalSpy loaded(window.get(), &MainWindow::animationLoaded);
    QSignalSpy canceled(window->animationOpener(), &AnimationOpener::canceled);
    window->animationOpener()->setProgressDelay(0);
    window->openAnimation(testAnimation("retriangulated"));
    QPointer<QProgressDialog> progress = window->animationOpener()->progressDialog();
    QVERIFY(progress);
    QVERIFY(window->isLoading());
    emit progress->canceled(); // what its Cancel button sends
    QCOMPARE(canceled.count(), 1);
    QVERIFY(!window->isLoading());
    QVERIFY(QThreadPool::globalInstance()->waitForDone(kWaitMs));
    QTest::qWait(50); // deliver the worker's end
    QCOMPARE(loaded.count(), 0);
    QCOMPARE(QString::fromStdString(window->scene()->source), bar);
}

// Run in the background, then the h slider by keyboard: the count shown is the core's
// segment(h) count for the same settings, and the labels are the core's labels.
void TestAnimationPanel::runAndHSliderFollowTheCore()
{
    if (!QFileInfo::exists(walkingCat()))
        QSKIP("../shared/data/anim/walking-cat is missing");
    auto window = showWindow(QStringLiteral("run"));
    QVERIFY(openAndWait(*window, walkingCat()));
    SegmentationPanel* panel = window->animationWorkspace()->segmentationPanel();
    auto* clusters = child<QSpinBox>(panel, "clustersSpinBox");
    typeInto(clusters, 6);
    QCOMPARE(panel->choices().clusters, 6);
    auto* run = child<QPushButton>(panel, "runSegmentationButton");
    QCOMPARE(run->text(), QStringLiteral("Run"));
    QTest::mouseClick(run, Qt::LeftButton);
    QVERIFY(panel->isRunning());
    QVERIFY(!run->isEnabled());
    QVERIFY(QTest::qWaitFor([&] { return panel->result() && !panel->isRunning(); }, kWaitMs));
    QVERIFY(run->isEnabled());
    QVERIFY(child<QLabel>(panel, "segmentationTimesLabel")->text().contains(QStringLiteral("partitions")));
    // The status names the animation's pose count (it said one pose fewer: the partitions).
    const QString done = child<QLabel>(panel, "segmentationStatusLabel")->text();
    QVERIFY2(done.contains(QStringLiteral("%1 poses").arg(window->animation()->animation->poseCount())),
             qPrintable(done));

    SegmenterSettings settings = SegmentationChoices{}.segmenterSettings();
    settings.partition.clusters = 6;
    AnimationSegmenter core(loadAnimation(walkingCat().toStdString()), settings);
    core.run();
    auto* slider = child<QSlider>(panel, "hSlider");
    auto* count = child<QLabel>(panel, "segmentCountLabel");
    slider->setFocus();
    std::map<int, std::uint32_t> counts;
    for (const Qt::Key key : {Qt::Key_Home, Qt::Key_PageUp, Qt::Key_Right, Qt::Key_PageUp, Qt::Key_End}) {
        QTest::keyClick(slider, key);
        const double h = double(slider->value()) / SegmentationPanel::kHSteps;
        QCOMPARE(panel->choices().h, h);
        const VertexLabeling expected = core.segment(h);
        QVERIFY(
            QTest::qWaitFor([&] { return panel->shownLabeling() && *panel->shownLabeling() == expected; }, kWaitMs));
        QVERIFY2(count->text().startsWith(QStringLiteral("Segments: %1 ").arg(expected.count)),
                 qPrintable(count->text()));
        counts[slider->value()] = expected.count;
    }
    qInfo("segments at h=0: %u, h=1: %u; last h change: segment(h) %.3f ms, recolor + pack %.3f ms", counts[0],
          counts[SegmentationPanel::kHSteps], panel->lastCleaningMs(), panel->lastColoringMs());
    QVERIFY(counts[SegmentationPanel::kHSteps] < counts[0]);
}

// Color by segment: every shown pixel whose triangle lies inside one segment has that
// segment's hue; off brings the trim palette back.
void TestAnimationPanel::colorBySegmentShowsSegmentColors()
{
    if (!QFileInfo::exists(walkingCat()))
        QSKIP("../shared/data/anim/walking-cat is missing");
    auto window = segmentedCat(QStringLiteral("colors"), QSize(384, 288));
    QVERIFY(window);
    SegmentationPanel* panel = window->animationWorkspace()->segmentationPanel();
    ViewportWidget* viewport = window->viewport();
    auto* toggle = child<QCheckBox>(panel, "colorBySegmentCheckBox");
    QVERIFY(toggle->isChecked()); // the default
    QVERIFY(QTest::qWaitFor([&] { return viewport->content()->colorOwner() == render::ContentOwner::Segmentation; },
                            kWaitMs));
    QVERIFY(waitForNewFrame(*window, [&] { viewport->update(); }));

    // Shading multiplies the interpolated color by one factor (ambient + diffuse, × 0.55 on
    // back faces), which keeps its hue; inside a one-segment triangle the interpolated color
    // is that segment's color. What remains is 8-bit rounding of the uploaded color and of
    // the framebuffer: with a chroma of at least 48 levels the hue moves by at most
    // 60° × 2 / 48 = 2.5°, so 4° is safe, while palette hues lie 15° or more apart.
    constexpr int kMinChroma = 48;
    constexpr double kHueTolerance = 4.0;
    const auto checkColors = [&](int& checked, std::set<std::uint32_t>& labelsSeen) {
        const TrimImage trim = viewport->readTrimImage();
        const QImage color = viewport->readColorImage();
        const VertexLabeling& labeling = *panel->shownLabeling();
        const std::vector<glm::vec3> rgb = colorsRgb(*panel->shownColors());
        const auto& triangles = window->scene()->scene.objects.front().mesh.triangles;
        int wrong = 0;
        for (int y = 0; y < trim.height; ++y) {
            for (int x = 0; x < trim.width; ++x) {
                const TrimPixel& pixel = trim.at(x, y);
                if (!pixel.covered())
                    continue;
                const glm::uvec3 t = triangles[std::size_t(pixel.primitiveId)];
                const std::uint32_t label = labeling.labels[t.x];
                if (labeling.labels[t.y] != label || labeling.labels[t.z] != label)
                    continue; // a border triangle blends two colors
                const std::optional<double> hue = hueOf(color.pixelColor(x, y), kMinChroma);
                const std::optional<double> expected =
                    hueOf(QColor::fromRgbF(rgb[label].r, rgb[label].g, rgb[label].b), 1);
                if (!hue || !expected)
                    continue;
                ++checked;
                labelsSeen.insert(label);
                wrong += hueDistanceDegrees(*hue, *expected) > kHueTolerance ? 1 : 0;
            }
        }
        return wrong;
    };
    int checked = 0;
    std::set<std::uint32_t> labelsSeen;
    QCOMPARE(checkColors(checked, labelsSeen), 0);
    qInfo("%d pixels of %zu segments checked", checked, labelsSeen.size());
    QVERIFY(checked > 1000);
    QVERIFY(labelsSeen.size() >= 4);

    QVERIFY(waitForNewFrame(*window, [&] { QTest::keyClick(toggle, Qt::Key_Space); }));
    QVERIFY(!toggle->isChecked());
    QCOMPARE(viewport->content()->colorOwner(), render::ContentOwner::None);
    QVERIFY(panel->displayColors().empty());
    const QImage plain = viewport->readColorImage();
    const TrimImage trim = viewport->readTrimImage();
    const double frontHue = *hueOf(QColor::fromRgbF(kFrontFacingColor.r, kFrontFacingColor.g, kFrontFacingColor.b), 1);
    int front = 0;
    for (int y = 0; y < trim.height; ++y)
        for (int x = 0; x < trim.width; ++x)
            if (trim.at(x, y).facing > 0)
                if (const auto hue = hueOf(plain.pixelColor(x, y), kMinChroma)) {
                    QVERIFY(hueDistanceDegrees(*hue, frontHue) <= kHueTolerance);
                    ++front;
                }
    QVERIFY(front > 500);
}

// Cancel while a run is under way (held at its first progress report, so that Cancel
// certainly comes during the run): the UI stays usable on the previous result, which
// survives the cancellation unchanged.
void TestAnimationPanel::cancelKeepsThePreviousResult()
{
    if (!QFileInfo::exists(walkingCat()))
        QSKIP("../shared/data/anim/walking-cat is missing");
    auto window = segmentedCat(QStringLiteral("cancel-run"));
    QVERIFY(window);
    SegmentationPanel* panel = window->animationWorkspace()->segmentationPanel();
    const std::shared_ptr<const SegmentationResult> previous = panel->result();
    typeInto(child<QSpinBox>(panel, "clustersSpinBox"), 12);

    test::HeldBackgroundJob held(panel->runTask());
    QTest::mouseClick(child<QPushButton>(panel, "runSegmentationButton"), Qt::LeftButton);
    QVERIFY(held.waitUntilHeld(kWaitMs));
    auto* cancel = child<QPushButton>(panel, "cancelSegmentationButton");
    QVERIFY(cancel->isEnabled());
    QTest::mouseClick(cancel, Qt::LeftButton);
    QVERIFY(!cancel->isEnabled()); // canceling
    QVERIFY(panel->isRunning());

    // Meanwhile the slider still re-cleans the previous result.
    auto* slider = child<QSlider>(panel, "hSlider");
    QTest::keyClick(slider, Qt::Key_PageUp);
    const VertexLabeling expected = previous->segmenter->segment(panel->choices().h);
    QVERIFY(QTest::qWaitFor([&] { return panel->shownLabeling() && *panel->shownLabeling() == expected; }, kWaitMs));

    held.release();
    QVERIFY(QTest::qWaitFor([&] { return !panel->isRunning(); }, kWaitMs));
    QCOMPARE(panel->result(), previous);
    QVERIFY(child<QLabel>(panel, "segmentationStatusLabel")->text().contains(QStringLiteral("Canceled")));
    QVERIFY(child<QPushButton>(panel, "runSegmentationButton")->isEnabled());
    QCOMPARE(*panel->shownLabeling(), expected);
}

// Real-time mode: "Stream poses" plays the timeline and appends every pose; afterwards
// the labels equal those of the global run (the core's guarantee, wired through the panel).
void TestAnimationPanel::realTimeStreamEqualsTheGlobalRun()
{
    if (!QFileInfo::exists(walkingCat()))
        QSKIP("../shared/data/anim/walking-cat is missing");
    auto window = segmentedCat(QStringLiteral("stream"));
    QVERIFY(window);
    SegmentationPanel* panel = window->animationWorkspace()->segmentationPanel();
    const VertexLabeling global = *panel->shownLabeling();
    QCOMPARE(global, referenceCat().segment(panel->choices().h));
    typeInto(child<QSpinBox>(window.get(), "fpsSpinBox"), TimelinePanel::kMaxFps);

    auto* mode = child<QComboBox>(panel, "modeComboBox");
    QTest::keyClick(mode, Qt::Key_Down);
    QCOMPARE(panel->choices().mode, SegmentationMode::RealTime);
    auto* run = child<QPushButton>(panel, "runSegmentationButton");
    QCOMPARE(run->text(), QStringLiteral("Stream poses"));
    QSignalSpy steps(panel->stream(), &SegmentStream::stepped);
    QTest::mouseClick(run, Qt::LeftButton);
    QVERIFY(window->animationWorkspace()->timelinePanel()->isPlaying());
    QVERIFY(panel->stream()->isRunning());
    QVERIFY(QTest::qWaitFor([&] { return !panel->isRunning(); }, kWaitMs));
    const int poses = int(window->animation()->animation->poseCount());
    QCOMPARE(steps.count(), poses);
    QVERIFY(child<QLabel>(panel, "segmentationStatusLabel")->text().contains(QStringLiteral("%1 poses").arg(poses)));
    QCOMPARE(*panel->shownLabeling(), global);
    QCOMPARE(panel->result()->segmenter->overSegmentation(), referenceCat().overSegmentation());
    QCOMPARE(window->viewport()->content()->colorOwner(), render::ContentOwner::Segmentation);
    QTest::mouseClick(child<QToolButton>(window.get(), "playButton"), Qt::LeftButton); // pause
}

// Variable mode: each timeline pose shows its partition joined with the next, colored by
// the pose-to-pose sequence; h does not apply.
void TestAnimationPanel::variableModeShowsEachPose()
{
    if (!QFileInfo::exists(walkingCat()))
        QSKIP("../shared/data/anim/walking-cat is missing");
    auto window = segmentedCat(QStringLiteral("variable"));
    QVERIFY(window);
    SegmentationPanel* panel = window->animationWorkspace()->segmentationPanel();
    auto* mode = child<QComboBox>(panel, "modeComboBox");
    QTest::keyClick(mode, Qt::Key_End);
    QCOMPARE(panel->choices().mode, SegmentationMode::Variable);
    QVERIFY(!child<QSlider>(panel, "hSlider")->isEnabled());

    const AnimationSegmenter& core = referenceCat();
    const std::vector<VertexLabeling> variable = core.variableSegmentation();
    const auto colors = colorSequence(core.graph(), core.vertexAreas(), variable);
    auto* slider = child<QSlider>(window.get(), "poseSlider");
    slider->setFocus();
    std::vector<std::uint32_t> previous;
    for (const int pose : {3, 13, 23}) {
        while (slider->value() != pose)
            QTest::keyClick(slider, slider->value() < pose ? Qt::Key_Right : Qt::Key_Left);
        // Rotation against the rest pose partitions poses 1 … 34: pose p is entry p − 1.
        QCOMPARE(*panel->shownLabeling(), variable[std::size_t(pose - 1)]);
        QCOMPARE(*panel->shownColors(), colors[std::size_t(pose - 1)]);
        QVERIFY(child<QLabel>(panel, "segmentCountLabel")->text().contains(QStringLiteral("pose %1").arg(pose)));
        QVERIFY(panel->displayColors() != previous);
        previous = panel->displayColors();
    }
}

// Export: JSON with the documented fields (docs/segmentation-format.md), CSV, and a glTF
// that loads back with loadMesh and carries _SEGMENT and COLOR_0.
void TestAnimationPanel::exportWritesJsonCsvAndGltf()
{
    if (!QFileInfo::exists(walkingCat()))
        QSKIP("../shared/data/anim/walking-cat is missing");
    auto window = segmentedCat(QStringLiteral("export"));
    QVERIFY(window);
    SegmentationPanel* panel = window->animationWorkspace()->segmentationPanel();
    const VertexLabeling shown = *panel->shownLabeling();
    const MeshAnimation& animation = *window->animation()->animation;

    const QString json = m_dir.filePath(QStringLiteral("cat.json"));
    QString error;
    QVERIFY2(panel->exportSegmentation(json, &error), qPrintable(error));
    QFile jsonFile(json);
    QVERIFY(jsonFile.open(QIODevice::ReadOnly));
    const QJsonObject document = QJsonDocument::fromJson(jsonFile.readAll()).object();
    QCOMPARE(document.value("format").toString(), QStringLiteral("trimlab-segmentation"));
    QCOMPARE(document.value("version").toInt(), 1);
    QCOMPARE(document.value("source").toString(), walkingCat());
    QCOMPARE(document.value("vertex_count").toInt(), int(animation.vertexCount()));
    QCOMPARE(document.value("pose_count").toInt(), int(animation.poseCount()));
    QCOMPARE(document.value("mode").toString(), QStringLiteral("global"));
    QCOMPARE(document.value("h").toDouble(), panel->choices().h);
    QCOMPARE(document.value("segment_count").toInt(), int(shown.count));
    QCOMPARE(document.value("segments").toArray().size(), qsizetype(shown.count));
    const QJsonArray labels = document.value("labels").toArray();
    QCOMPARE(labels.size(), qsizetype(shown.labels.size()));
    for (qsizetype v = 0; v < labels.size(); ++v)
        QCOMPARE(labels[v].toInt(), int(shown.labels[std::size_t(v)]));
    const QJsonObject times = document.value("times_ms").toObject();
    for (const char* stage : {"load", "features", "partitions", "over_segmentation", "cleaning"})
        QVERIFY2(times.contains(QLatin1String(stage)), stage);
    QVERIFY(times.value("features").toDouble() > 0.0);
    QVERIFY(times.value("load").toDouble() > 0.0);

    const QString csv = m_dir.filePath(QStringLiteral("cat.csv"));
    QVERIFY2(panel->exportSegmentation(csv, &error), qPrintable(error));
    QFile csvFile(csv);
    QVERIFY(csvFile.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = csvFile.readAll().trimmed().split('\n');
    QCOMPARE(lines.front(), QByteArray("vertex,label"));
    QCOMPARE(lines.size(), qsizetype(animation.vertexCount() + 1));

    const QString gltf = m_dir.filePath(QStringLiteral("cat.gltf"));
    QVERIFY2(panel->exportSegmentation(gltf, &error), qPrintable(error));
    const TriangleMesh mesh = loadMesh(gltf.toStdString());
    QCOMPARE(mesh.triangleCount(), animation.triangleCount());
    QFile gltfFile(gltf);
    QVERIFY(gltfFile.open(QIODevice::ReadOnly));
    const QJsonObject model = QJsonDocument::fromJson(gltfFile.readAll()).object();
    const QJsonObject attributes = model["meshes"][0]["primitives"][0]["attributes"].toObject();
    QVERIFY(attributes.contains("COLOR_0"));
    QVERIFY(attributes.contains("_SEGMENT"));
    const int segmentAccessor = attributes["_SEGMENT"].toInt();
    QCOMPARE(model["accessors"][segmentAccessor]["count"].toInt(), int(animation.vertexCount()));
    QCOMPARE(model["asset"]["extras"]["segment_count"].toInt(), int(shown.count));

    // Variable mode adds the per-pose segmentations.
    QTest::keyClick(child<QComboBox>(panel, "modeComboBox"), Qt::Key_End);
    const QString variableJson = m_dir.filePath(QStringLiteral("cat-variable.json"));
    QVERIFY2(panel->exportSegmentation(variableJson, &error), qPrintable(error));
    QFile variableFile(variableJson);
    QVERIFY(variableFile.open(QIODevice::ReadOnly));
    const QJsonObject variable = QJsonDocument::fromJson(variableFile.readAll()).object();
    QCOMPARE(variable.value("mode").toString(), QStringLiteral("variable"));
    QCOMPARE(variable.value("variable").toArray().size(), qsizetype(animation.poseCount() - 1));

    QVERIFY(!panel->exportSegmentation(m_dir.filePath(QStringLiteral("cat.txt")), &error));
    QVERIFY(error.contains(QStringLiteral(".json")));
}

// Every segmentation and playback choice survives into a new window.
void TestAnimationPanel::choicesPersist()
{
    const QString settings = QStringLiteral("persist");
    {
        auto window = showWindow(settings);
        QVERIFY(openAndWait(*window, testAnimation("bar")));
        SegmentationPanel* panel = window->animationWorkspace()->segmentationPanel();
        QTest::keyClick(child<QComboBox>(panel, "referenceComboBox"), Qt::Key_End);  // previous pose
        QTest::keyClick(child<QComboBox>(panel, "featureComboBox"), Qt::Key_End);    // acceleration
        QTest::keyClick(child<QComboBox>(panel, "clusteringComboBox"), Qt::Key_End); // hierarchical
        typeInto(child<QSpinBox>(panel, "clustersSpinBox"), 11);
        typeInto(child<QSpinBox>(panel, "threadsSpinBox"), 2);
        QTest::keyClick(child<QSlider>(panel, "hSlider"), Qt::Key_End);                    // h = 1
        QTest::keyClick(child<QComboBox>(panel, "modeComboBox"), Qt::Key_End);             // variable
        QTest::keyClick(child<QCheckBox>(panel, "colorBySegmentCheckBox"), Qt::Key_Space); // off
        typeInto(child<QSpinBox>(window.get(), "fpsSpinBox"), 30);
        QTest::keyClick(child<QCheckBox>(window.get(), "loopCheckBox"), Qt::Key_Space);
        QTest::keyClick(child<QComboBox>(window.get(), "poseRuleCombo"), Qt::Key_End);      // constructive intersection
        QTest::keyClick(child<QComboBox>(window.get(), "poseReferenceCombo"), Qt::Key_End); // rest pose
        window->close();
    }
    auto window = showWindow(settings);
    const SegmentationChoices restored = window->animationWorkspace()->segmentationPanel()->choices();
    QCOMPARE(restored.feature, FeatureKind::Acceleration);
    QCOMPARE(restored.reference, ReferenceMode::Previous);
    QCOMPARE(restored.method, PartitionMethod::Hierarchical);
    QCOMPARE(restored.clusters, 11);
    QCOMPARE(restored.threads, 2);
    QCOMPARE(restored.mode, SegmentationMode::Variable);
    QVERIFY(!restored.colorBySegment);
    QCOMPARE(restored.h, 1.0);
    QCOMPARE(window->animationWorkspace()->timelinePanel()->fps(), 30);
    QVERIFY(!window->animationWorkspace()->timelinePanel()->loops());
    const PoseHistoryChoices history = window->animationWorkspace()->poseHistoryBar()->choices();
    QCOMPARE(history.rule, std::optional<DynamicRule>(DynamicRule::ConstructiveIntersection));
    QCOMPARE(history.reference, PoseReference::Rest);
    QCOMPARE(window->recentAnimations().value(0), QFileInfo(testAnimation("bar")).absoluteFilePath());
    QVERIFY(!window->findChild<QDockWidget*>(QStringLiteral("timelineDock"))->isVisible()); // no animation yet
}

// The window with the walking cat segmented and colored, at a pose mid-stride, without
// the first-start clip plane (docs/screenshot-segmentation.png).
void TestAnimationPanel::screenshot()
{
    if (!QFileInfo::exists(walkingCat()))
        QSKIP("../shared/data/anim/walking-cat is missing");
    auto window = segmentedCat(QStringLiteral("screenshot"), QSize());
    QVERIFY(window);
    window->resize(1280, 800);
    window->findChild<QDockWidget*>(QStringLiteral("frameStatsDock"))->hide(); // room for the panel
    RenderChoices choices = window->renderWorkspace()->panel()->renderChoices();
    choices.trim.clip.enabled = false;
    window->renderWorkspace()->panel()->setRenderChoices(choices);
    emit window->renderWorkspace()->panel()->renderChoicesChanged();
    QVERIFY(waitForNewFrame(*window, [&] { window->animationWorkspace()->timelinePanel()->setPose(12); }));
    QTest::qWait(200); // let the layout and status bar settle
    const QString shot = QString::fromStdString((test::outputDir() / "segmentation-window.png").string());
    QVERIFY(window->grab().save(shot));
    qInfo("screenshot: %s", qPrintable(shot));
}

TRIMLAB_WIDGET_TEST_MAIN(TestAnimationPanel)
#include "tst_animation_panel.moc"
