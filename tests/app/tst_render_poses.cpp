// `trimlab render ANIMATION --pose N | --poses A:B` as scripts call it: one image per
// pose, named by the pattern, all with one camera fitted to the poses together, each
// pose's ids agreeing with the CPU reference of that pose; bad selections and patterns
// fail with one line before any work; --close-holes makes an open animation trimmable.
#include "gl_test_context.h"
#include "ids_png.h"
#include "meeting_balls.h"
#include "run_trimlab.h"
#include "test_paths.h"
#include "trim_comparison.h"

#include "app/pose_frames.h"
#include "core/animation/animation_chain.h"
#include "core/animation/animation_loader.h"
#include "core/animation/pose_sets.h"
#include "core/trim/dynamic_reference_renderer.h"
#include "core/trim/reference_renderer.h"

#include <QTemporaryDir>
#include <QtTest>

#include <filesystem>

using namespace trimlab;
using trimlab::test::Run;
using trimlab::test::runTrimlab;

namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 120;

QString animation(const char* relative)
{
    return QString::fromStdString(test::testDataPath(std::string("animations/") + relative).string());
}

} // namespace

namespace {

// The camera `trimlab render --poses` fits to every pose of `animation` at kWidth × kHeight.
Camera camerasOfAllPoses(const MeshAnimation& animation)
{
    Bounds together;
    for (std::size_t p = 0; p < animation.poseCount(); ++p)
        together.extend(computeBounds(animation.poseMesh(p)));
    return fitCamera(together, double(kWidth) / kHeight);
}

// --rule parity --clip 0,0,-1,0: the two balls cut open through their centres.
TrimSettings parityCutOpen()
{
    TrimSettings settings;
    settings.rule = StaticRule::Parity;
    settings.clip = ClipPlane{true, {0.0, 0.0, -1.0}, 0.0};
    return settings;
}

} // namespace

class TestRenderPoses : public QObject {
    Q_OBJECT
private slots:
    void poseNumbersInFileNames();
    void badSelectionsFailFast_data();
    void badSelectionsFailFast();
    void posesAgreeWithTheReference();
    void onePoseOnTheReferenceBackend();
    void dynamicRulesOverTheAnimation_data();
    void dynamicRulesOverTheAnimation();
    void poseSetsOverTheAnimation();
    void closeHolesTrimsAnOpenAnimation();

private:
    QTemporaryDir m_dir;
};

void TestRenderPoses::poseNumbersInFileNames()
{
    using app::hasPoseNumber;
    using app::posePath;
    QVERIFY(hasPoseNumber("frame_%04d.png"));
    QVERIFY(hasPoseNumber("%d.png"));
    QVERIFY(hasPoseNumber("100%%_%03d.png"));
    QVERIFY(!hasPoseNumber("frame.png"));
    QVERIFY(!hasPoseNumber("frame_%4d.png")); // space padding has no place in a file name
    QVERIFY(!hasPoseNumber("%d_%d.png"));
    QVERIFY(!hasPoseNumber("frame_%s.png"));
    QVERIFY(!hasPoseNumber("frame_%"));
    QCOMPARE(posePath("frame_%04d.png", 7), QStringLiteral("frame_0007.png"));
    QCOMPARE(posePath("frame_%04d.png", 123456), QStringLiteral("frame_123456.png"));
    QCOMPARE(posePath("%d.png", 42), QStringLiteral("42.png"));
    QCOMPARE(posePath("100%%_%03d.png", 5), QStringLiteral("100%_005.png"));
    QCOMPARE(posePath("still.png", 5), QStringLiteral("still.png"));
}

void TestRenderPoses::badSelectionsFailFast_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    QTest::addColumn<int>("exitCode"); // 2: the command line; 1: the input
    const QString box = animation("folding_box");
    QTest::newRow("both") << QStringList{"render", box, "--pose", "1", "--poses", "0:2", "-o", "f_%d.png"} << "not both"
                          << 2;
    QTest::newRow("no number in -o") << QStringList{"render", box, "--poses", "0:2", "-o", "f.png"}
                                     << "f.png' needs the pose number" << 2;
    QTest::newRow("no number in --ids") << QStringList{"render", box,        "--poses", "0:2",
                                                       "-o",     "f_%d.png", "--ids",   "ids.png"}
                                        << "ids.png' needs the pose number" << 2;
    QTest::newRow("backwards") << QStringList{"render", box, "--poses", "2:0", "-o", "f_%d.png"} << "runs backwards"
                               << 2;
    QTest::newRow("not a range") << QStringList{"render", box, "--poses", "0-2", "-o", "f_%d.png"} << "not a range A:B"
                                 << 2;
    QTest::newRow("negative") << QStringList{"render", box, "--pose", "-1", "-o", "f.png"} << "not a pose number" << 2;
    QTest::newRow("two sources") << QStringList{"render", box, box, "--pose", "0", "-o", "f.png"}
                                 << "one mesh animation source" << 2;
    QTest::newRow("csg") << QStringList{"render", box, "--pose", "0", "--csg", "0 - 1", "-o", "f.png"}
                         << "an animation is one object" << 2;
    QTest::newRow("pose beyond the last")
        << QStringList{"render", box, "--pose", "3", "-o", "f.png", "--backend", "reference"}
        << "has 3 poses (0 to 2); pose 3 does not exist" << 2;
    QTest::newRow("sets not after the rest pose")
        << QStringList{"render",      box,  "--poses",  "0:2",       "--sets",
                       "2:confluent", "-o", "f_%d.png", "--backend", "reference"}
        << "the first set must start right after the rest pose 0, at pose 1, not 2" << 2;
    QTest::newRow("sets with a dynamic rule")
        << QStringList{"render",         box,        "--poses", "0:2",     "--sets", "1:confluent",
                       "--dynamic-rule", "additive", "-o",      "f_%d.png"}
        << "leave out --dynamic-rule" << 2;
    QTest::newRow("sets with a bad rule")
        << QStringList{"render", box, "--poses", "0:2", "--sets", "1:union", "-o", "f_%d.png"}
        << "--sets: unknown rule 'union'" << 2;
    QTest::newRow("poses of different sizes")
        << QStringList{"render",    animation("mismatched_vertices/mesh_%04d.obj"),
                       "--pose",    "0",
                       "-o",        "f.png",
                       "--backend", "reference"}
        << "mesh_0001.obj" << 1;
}

void TestRenderPoses::badSelectionsFailFast()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    QFETCH(int, exitCode);
    for (QString& argument : arguments)
        if (argument.startsWith(QLatin1String("f")) || argument.startsWith(QLatin1String("ids")))
            argument = m_dir.filePath(argument);
    const Run run = runTrimlab(arguments);
    QCOMPARE(run.exitCode, exitCode);
    QVERIFY2(run.err.contains(message), qPrintable(run.err));
    QVERIFY2(run.err.count(QLatin1Char('\n')) <= 1, qPrintable(run.err)); // one line
    QVERIFY(!QFileInfo::exists(m_dir.filePath("f.png")) && !QFileInfo::exists(m_dir.filePath("f_0.png")));
}

// The folding box's first two poses on the GPU: two images and two ids files; each
// pose's ids agree with the CPU reference of that pose seen from the camera fitted to the
// poses together (so the frames line up); the box moves between the poses. (Its last
// pose folds the box flat: faces closer than float depth resolution make 5.6 % of its
// pixels depth-order ties, beyond what the comparison excludes.)
void TestRenderPoses::posesAgreeWithTheReference()
{
    TRIMLAB_SKIP_WITHOUT_GL();
    const Run run =
        runTrimlab({"render", animation("folding_box"), "--poses", "0:1", "--rule", "alternating-border", "--method",
                    "abuffer-linked-list", "--size", QStringLiteral("%1x%2").arg(kWidth).arg(kHeight), "--ids",
                    m_dir.filePath("ids_%d.png"), "-o", m_dir.filePath("frame_%03d.png")});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    QVERIFY2(run.out.contains("folding_box, pose 1 of 2") && run.out.contains("frame_001.png"), qPrintable(run.out));
    QVERIFY(!QFileInfo::exists(m_dir.filePath("frame_002.png")));

    const MeshAnimation box = loadAnimation(animation("folding_box").toStdString());
    QCOMPARE(box.poseCount(), std::size_t(3));
    Bounds together;
    for (std::size_t p = 0; p < 2; ++p)
        together.extend(computeBounds(box.poseMesh(p)));
    const Camera camera = fitCamera(together, double(kWidth) / kHeight);
    TrimSettings settings;
    settings.rule = StaticRule::AlternatingBorder;
    std::vector<TrimImage> shown;
    for (int pose = 0; pose < 2; ++pose) {
        QVERIFY(QFileInfo::exists(m_dir.filePath(QStringLiteral("frame_%1.png").arg(pose, 3, 10, QLatin1Char('0')))));
        const QImage ids(m_dir.filePath(QStringLiteral("ids_%1.png").arg(pose)));
        QVERIFY(!ids.isNull());
        Scene scene;
        scene.objects.push_back({"box", box.poseMesh(std::size_t(pose)), glm::dmat4(1.0)});
        const ReferenceResult reference = ReferenceRenderer(scene).render(camera, kWidth, kHeight, settings);
        shown.push_back(test::decodeIdsPng(ids));
        const test::TrimComparison comparison =
            test::compareTrimImages(shown.back(), test::idsOnly(reference.trim), reference.diagnostics);
        qInfo("pose %d: %s", pose, qPrintable(comparison.summary()));
        QVERIFY(comparison.coveredPixels > 300);
        QVERIFY2(comparison.agreement() >= 0.999 && comparison.excludedFraction() <= 0.05,
                 qPrintable(comparison.summary()));
    }
    int moved = 0;
    for (std::size_t p = 0; p < shown.front().pixels.size(); ++p)
        moved += shown.front().pixels[p].covered() != shown.back().pixels[p].covered() ? 1 : 0;
    QVERIFY2(moved > 50, qPrintable(QString::number(moved)));
}

void TestRenderPoses::onePoseOnTheReferenceBackend()
{
    const QString out = m_dir.filePath("one.png");
    const Run run =
        runTrimlab({"render", animation("bar"), "--pose", "1", "--backend", "reference", "--size", "64x48", "-o", out});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    QVERIFY2(run.out.contains("bar, pose 1 of") && run.out.contains("reference ray caster"), qPrintable(run.out));
    QVERIFY(!QImage(out).isNull());
}

void TestRenderPoses::dynamicRulesOverTheAnimation_data()
{
    QTest::addColumn<QString>("rule");
    QTest::addColumn<QString>("reference");
    QTest::newRow("additive, rest") << "additive"
                                    << "rest";
    QTest::newRow("confluent, previous") << "confluent"
                                         << "previous";
    QTest::newRow("subtractive, previous") << "subtractive"
                                           << "previous";
}

// Two balls of one mesh that move into each other over three poses (apart, touching
// deep, deeper): each pose under a dynamic rule, on the GPU, against the dynamic CPU
// reference of the chain that animationChain builds for it, cut open by a plane through
// the balls' centres. Under parity alone the lens where they overlap (winding 2) is
// carved out and its walls show through the cut; the history (both balls solid before
// they met) keeps it solid under the additive and confluent rules, and the subtractive
// rule removes what moved, so the images differ from parity's.
void TestRenderPoses::dynamicRulesOverTheAnimation()
{
    TRIMLAB_SKIP_WITHOUT_GL();
    QFETCH(QString, rule);
    QFETCH(QString, reference);
    const QString folder = m_dir.filePath("balls");
    if (!QFileInfo::exists(folder))
        QVERIFY(test::writeMeetingBalls(folder));
    const QString tag = rule + QLatin1Char('-') + reference;
    const QString size = QStringLiteral("%1x%2").arg(kWidth).arg(kHeight);
    const Run run = runTrimlab({"render",
                                folder,
                                "--poses",
                                "0:2",
                                "--rule",
                                "parity",
                                "--clip",
                                "0,0,-1,0",
                                "--dynamic-rule",
                                rule,
                                "--reference",
                                reference,
                                "--method",
                                "abuffer-linked-list",
                                "--size",
                                size,
                                "--ids",
                                m_dir.filePath(tag + "-ids_%d.png"),
                                "-o",
                                m_dir.filePath(tag + "_%d.png")});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    QVERIFY2(
        run.out.contains(QStringLiteral("%1 against the %2 pose (parity on the rest pose 0)").arg(rule, reference)),
        qPrintable(run.out));
    // Against the previous pose, pose 2's history is pose 1's plus a set: only that set is
    // characterized (the viewport's timeline carries the classification the same way).
    if (reference == QLatin1String("previous"))
        QVERIFY2(QRegularExpression(
                     QStringLiteral("pose 2 of 2: .*dynamic rules: 2 sets, [0-9.]+ ms to characterize 1 of them"))
                     .match(run.out)
                     .hasMatch(),
                 qPrintable(run.out));
    // The same poses under parity alone (the same camera: fitted to the same poses).
    const Run still = runTrimlab({"render", folder, "--poses", "0:2", "--rule", "parity", "--clip", "0,0,-1,0",
                                  "--method", "abuffer-linked-list", "--size", size, "--ids",
                                  m_dir.filePath("static-ids_%d.png"), "-o", m_dir.filePath("static_%d.png")});
    QVERIFY2(still.exitCode == 0, qPrintable(still.err));

    const MeshAnimation balls = loadAnimation(folder.toStdString());
    const Camera camera = camerasOfAllPoses(balls);
    const TrimSettings settings = parityCutOpen();
    for (std::size_t pose = 1; pose < 3; ++pose) {
        const DynamicChain chain = animationChain(balls, pose, *parsePoseReference(reference.toStdString()),
                                                  *parseDynamicRule(rule.toStdString()), StaticRule::Parity)
                                       .value();
        QCOMPARE(chain.levels.size(), reference == QLatin1String("rest") ? std::size_t(1) : pose);
        const ReferenceResult expected = DynamicReferenceRenderer(chain).render(camera, kWidth, kHeight, settings);
        const TrimImage fromFile =
            test::decodeIdsPng(QImage(m_dir.filePath(tag + QStringLiteral("-ids_%1.png").arg(pose))));
        const test::TrimComparison comparison = test::compareTrimImages(
            fromFile, test::idsOnly(withMeshIds(expected.trim, chain.levels.back().frame)), expected.diagnostics);
        qInfo("pose %zu: %s", pose, qPrintable(comparison.summary()));
        QVERIFY(comparison.coveredPixels > 200); // the subtractive rule keeps little
        QVERIFY2(comparison.agreement() >= 0.999 && comparison.excludedFraction() <= 0.05,
                 qPrintable(comparison.summary()));
    }
    // The history matters: the last pose under the dynamic rule is not parity's picture.
    const TrimImage dynamicLast = test::decodeIdsPng(QImage(m_dir.filePath(tag + "-ids_2.png")));
    const TrimImage staticLast = test::decodeIdsPng(QImage(m_dir.filePath("static-ids_2.png")));
    int differing = 0;
    for (std::size_t p = 0; p < dynamicLast.pixels.size(); ++p)
        differing += dynamicLast.pixels[p].primitiveId != staticLast.pixels[p].primitiveId ? 1 : 0;
    qInfo("%d pixels differ from parity alone", differing);
    QVERIFY2(differing > 100, qPrintable(QString::number(differing)));
}

// The two balls as two sets with their own rules: pose 1 alone under the additive rule
// (against the rest pose), pose 2 a set of its own under the subtractive rule against
// pose 1. Each pose agrees with the exact reference of its chain; pose 2 appends its set
// to pose 1's history (one characterization), and the subtractive second set gives
// another picture than the additive rule over both poses.
void TestRenderPoses::poseSetsOverTheAnimation()
{
    TRIMLAB_SKIP_WITHOUT_GL();
    const QString folder = m_dir.filePath("balls");
    if (!QFileInfo::exists(folder))
        QVERIFY(test::writeMeetingBalls(folder));
    const QString size = QStringLiteral("%1x%2").arg(kWidth).arg(kHeight);
    const Run run = runTrimlab({"render", folder, "--poses", "0:2", "--rule", "parity", "--clip", "0,0,-1,0", "--sets",
                                "1:additive,2:subtractive", "--method", "abuffer-linked-list", "--size", size, "--ids",
                                m_dir.filePath("sets-ids_%d.png"), "-o", m_dir.filePath("sets_%d.png")});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    QVERIFY2(run.out.contains(QStringLiteral("subtractive against pose 1 (set 2 of 2 in 1:additive,2:subtractive; "
                                             "parity on the rest pose 0)")),
             qPrintable(run.out));
    QVERIFY2(
        QRegularExpression(QStringLiteral("pose 2 of 2: .*dynamic rules: 2 sets, [0-9.]+ ms to characterize 1 of them"))
            .match(run.out)
            .hasMatch(),
        qPrintable(run.out));
    const MeshAnimation balls = loadAnimation(folder.toStdString());
    const Camera camera = camerasOfAllPoses(balls);
    const TrimSettings settings = parityCutOpen();
    const std::vector<PoseSet> sets{{1, DynamicRule::ConstructiveAdditive}, {2, DynamicRule::ConstructiveSubtractive}};
    for (std::size_t pose = 1; pose < 3; ++pose) {
        const DynamicChain chain = poseSetChain(balls, pose, sets, StaticRule::Parity).value();
        QCOMPARE(chain.levels.size(), pose);
        const ReferenceResult expected = DynamicReferenceRenderer(chain).render(camera, kWidth, kHeight, settings);
        const TrimImage fromFile =
            test::decodeIdsPng(QImage(m_dir.filePath(QStringLiteral("sets-ids_%1.png").arg(pose))));
        const test::TrimComparison comparison = test::compareTrimImages(
            fromFile, test::idsOnly(withMeshIds(expected.trim, chain.levels.back().frame)), expected.diagnostics);
        qInfo("pose %zu: %s", pose, qPrintable(comparison.summary()));
        QVERIFY(comparison.coveredPixels > 200);
        QVERIFY2(comparison.agreement() >= 0.999 && comparison.excludedFraction() <= 0.05,
                 qPrintable(comparison.summary()));
    }
    // The second set's rule shows: not the picture of the additive rule over both poses.
    const DynamicChain additive =
        animationChain(balls, 2, PoseReference::Previous, DynamicRule::ConstructiveAdditive, StaticRule::Parity)
            .value();
    const TrimImage additiveIds =
        withMeshIds(DynamicReferenceRenderer(additive).render(camera, kWidth, kHeight, settings).trim,
                    additive.levels.back().frame);
    const TrimImage setsIds = test::decodeIdsPng(QImage(m_dir.filePath("sets-ids_2.png")));
    int differing = 0;
    for (std::size_t p = 0; p < setsIds.pixels.size(); ++p)
        differing += setsIds.pixels[p].primitiveId != additiveIds.pixels[p].primitiveId ? 1 : 0;
    QVERIFY2(differing > 100, qPrintable(QString::number(differing)));
}

// horse-gallop (../shared/data: a captured gallop with two holes, 19 edges in all, in every pose)
// cannot be trimmed as it is, and the refusal names the remedy. With --close-holes its
// pose 5 renders under the confluent rule against the previous pose, and both backends
// agree with the exact dynamic reference of the closed animation's chain (poses 1 to 5).
void TestRenderPoses::closeHolesTrimsAnOpenAnimation()
{
    TRIMLAB_SKIP_WITHOUT_GL();
    const std::filesystem::path horse = test::sharedDataPath("anim/horse-gallop");
    if (!std::filesystem::exists(horse))
        QSKIP("../shared/data/anim/horse-gallop is not here");
    const QString source = QString::fromStdString(horse.string());
    const QStringList pose5{
        "render",    source,        "--pose",   "5",      "--dynamic-rule",
        "confluent", "--reference", "previous", "--size", QStringLiteral("%1x%2").arg(kWidth).arg(kHeight)};
    const Run refused = runTrimlab(pose5 + QStringList{"-o", m_dir.filePath("horse-open.png")});
    QCOMPARE(refused.exitCode, 1);
    QVERIFY2(refused.err.contains("19 boundary edges") && refused.err.contains("--close-holes"),
             qPrintable(refused.err));
    QVERIFY(!QFileInfo::exists(m_dir.filePath("horse-open.png")));

    const QStringList closedPose5 = pose5 + QStringList{"--close-holes"};
    const Run gpu = runTrimlab(
        closedPose5 + QStringList{"--ids", m_dir.filePath("horse-ids.png"), "-o", m_dir.filePath("horse.png")});
    QVERIFY2(gpu.exitCode == 0, qPrintable(gpu.err));
    QVERIFY2(gpu.out.contains("confluent against the previous pose"), qPrintable(gpu.out));
    const Run cpu = runTrimlab(closedPose5 + QStringList{"--backend", "reference", "--ids",
                                                         m_dir.filePath("horse-reference-ids.png"), "-o",
                                                         m_dir.filePath("horse-reference.png")});
    QVERIFY2(cpu.exitCode == 0, qPrintable(cpu.err));

    AnimationLoadOptions load;
    load.closeHoles = true;
    const MeshAnimation closed = loadAnimation(horse.string(), load);
    QCOMPARE(closed.triangleCount(), loadAnimation(horse.string()).triangleCount() + 19);
    const Camera camera = fitCamera(computeBounds(closed.poseMesh(5)), double(kWidth) / kHeight);
    const DynamicChain chain =
        animationChain(closed, 5, PoseReference::Previous, DynamicRule::Confluent, StaticRule::AlternatingBorder)
            .value();
    QCOMPARE(chain.levels.size(), std::size_t(5));
    const ReferenceResult expected = DynamicReferenceRenderer(chain).render(camera, kWidth, kHeight, TrimSettings{});
    const TrimImage expectedIds = test::idsOnly(withMeshIds(expected.trim, chain.levels.back().frame));
    for (const char* file : {"horse-ids.png", "horse-reference-ids.png"}) {
        const test::TrimComparison comparison = test::compareTrimImages(
            test::decodeIdsPng(QImage(m_dir.filePath(QString::fromLatin1(file)))), expectedIds, expected.diagnostics);
        qInfo("%s: %s", file, qPrintable(comparison.summary()));
        QVERIFY(comparison.coveredPixels > 1000);
        QVERIFY2(comparison.agreement() >= 0.999 && comparison.excludedFraction() <= 0.05,
                 qPrintable(comparison.summary()));
    }
}

QTEST_MAIN(TestRenderPoses)
#include "tst_render_poses.moc"
