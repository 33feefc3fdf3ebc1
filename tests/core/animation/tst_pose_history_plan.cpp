// The pose-history plan (core/animation/pose_history_plan.h), table-driven: for sets on
// either side of the rest pose, a pose held and a pose wanted, the step (New, Append or
// ReplaceShown) and the exact levels it hands over; the chains it describes are the ones
// animation_chain.h frames; bad sets are refused with a reason.
#include "core/animation/animation_chain.h"
#include "core/animation/pose_history_plan.h"
#include "core/animation/pose_sets.h"

#include <QtTest>

#include <optional>
#include <stdexcept>
#include <string>

using namespace trimlab;

namespace {

using Kind = PoseHistoryStep::Kind;

// "ref>pose:rule" per level, separated by spaces.
QString levelsText(const std::vector<PoseHistoryLevel>& levels)
{
    QStringList parts;
    for (const PoseHistoryLevel& level : levels)
        parts << QStringLiteral("%1>%2:%3")
                     .arg(level.reference)
                     .arg(level.pose)
                     .arg(QString::fromLatin1(dynamicRuleName(level.rule).data()));
    return parts.join(QLatin1Char(' '));
}

std::vector<PoseSet> sets(const char* text)
{
    std::string error;
    const std::optional<std::vector<PoseSet>> parsed = parsePoseSets(text, error);
    if (!parsed)
        throw std::invalid_argument(error);
    return *parsed;
}

// Three sets after rest pose 0: poses 1–2 confluent, 3–4 additive, 5– intersection.
PoseHistorySets threeSets()
{
    return {0, sets("1:confluent,3:additive,5:intersection"), {}};
}

} // namespace

Q_DECLARE_METATYPE(trimlab::PoseHistorySets)
Q_DECLARE_METATYPE(trimlab::PoseHistoryStep::Kind)

class TestPoseHistoryPlan : public QObject {
    Q_OBJECT
private slots:
    void plan_data();
    void plan();
    void referenceHistoriesFrameAsAnimationChains();
    void setsFrameAsPoseSetChains();
    void refusesPosesWithoutSetsAndBadSets();
};

void TestPoseHistoryPlan::plan_data()
{
    QTest::addColumn<PoseHistorySets>("history");
    QTest::addColumn<int>("shown"); // −1: no chain held
    QTest::addColumn<int>("wanted");
    QTest::addColumn<Kind>("kind");
    QTest::addColumn<QString>("levels");

    const PoseHistorySets three = threeSets();
    QTest::newRow("nothing held: the whole chain") << three << -1 << 4 << Kind::New << "0>2:confluent 2>4:additive";
    QTest::newRow("same set: the shown level") << three << 3 << 4 << Kind::ReplaceShown << "2>4:additive";
    QTest::newRow("same pose again") << three << 4 << 4 << Kind::ReplaceShown << "2>4:additive";
    QTest::newRow("a set's last pose: its next set") << three << 2 << 3 << Kind::Append << "2>3:additive";
    QTest::newRow("a set's last pose: two sets on")
        << three << 2 << 6 << Kind::Append << "2>4:additive 4>6:intersection";
    QTest::newRow("inside a set: not a reference") << three << 1 << 3 << Kind::New << "0>2:confluent 2>3:additive";
    QTest::newRow("backwards") << three << 4 << 2 << Kind::New << "0>2:confluent";
    QTest::newRow("from the rest pose") << three << 0 << 1 << Kind::New << "0>1:confluent";
    QTest::newRow("to the rest pose: no chain") << three << 3 << 0 << Kind::New << "";

    const PoseHistorySets previous = referenceHistory(2, 6, PoseReference::Previous, DynamicRule::Confluent);
    QTest::newRow("previous: playing forward") << previous << 3 << 5 << Kind::Append << "3>4:confluent 4>5:confluent";
    QTest::newRow("previous: playing backward before the rest pose")
        << previous << 1 << 0 << Kind::Append << "1>0:confluent";
    QTest::newRow("previous: scrubbing back") << previous << 5 << 4 << Kind::New << "2>3:confluent 3>4:confluent";
    QTest::newRow("previous: across the rest pose") << previous << 3 << 1 << Kind::New << "2>1:confluent";

    const PoseHistorySets rest = referenceHistory(2, 6, PoseReference::Rest, DynamicRule::ConstructiveAdditive);
    QTest::newRow("rest: another pose after it") << rest << 3 << 5 << Kind::ReplaceShown << "2>5:additive";
    QTest::newRow("rest: another pose before it") << rest << 1 << 0 << Kind::ReplaceShown << "2>0:additive";
    QTest::newRow("rest: across it") << rest << 1 << 4 << Kind::New << "2>4:additive";
}

void TestPoseHistoryPlan::plan()
{
    QFETCH(PoseHistorySets, history);
    QFETCH(int, shown);
    QFETCH(int, wanted);
    QFETCH(Kind, kind);
    QFETCH(QString, levels);
    const std::optional<std::size_t> held = shown < 0 ? std::nullopt : std::optional(std::size_t(shown));
    const PoseHistoryStep step = planPoseHistory(history, held, std::size_t(wanted));
    QCOMPARE(step.kind, kind);
    QCOMPARE(levelsText(step.levels), levels);
}

// New's levels frame the chain animation_chain.h builds: the reference of the first
// level, then every level's pose, are chainPoses for every pose on both sides.
void TestPoseHistoryPlan::referenceHistoriesFrameAsAnimationChains()
{
    for (const PoseReference reference : {PoseReference::Rest, PoseReference::Previous}) {
        const std::size_t restPose = 3, poseCount = 7;
        const PoseHistorySets history = referenceHistory(restPose, poseCount, reference, DynamicRule::Confluent);
        for (std::size_t pose = 0; pose < poseCount; ++pose) {
            const std::vector<PoseHistoryLevel> levels = poseHistoryLevels(history, pose);
            std::vector<std::size_t> frames{restPose};
            for (const PoseHistoryLevel& level : levels) {
                QCOMPARE(level.reference, frames.back()); // each level starts where the one before ended
                frames.push_back(level.pose);
            }
            QCOMPARE(frames, chainPoses(restPose, pose, reference));
        }
    }
}

// Sets after the rest pose: each level is a set's reference against the next reference
// (the last: against the pose), with the set's rule — poseSetChain's frames and rules.
void TestPoseHistoryPlan::setsFrameAsPoseSetChains()
{
    const PoseHistorySets history = threeSets();
    for (std::size_t pose = 1; pose < 8; ++pose) {
        const std::vector<PoseHistoryLevel> levels = poseHistoryLevels(history, pose);
        const std::size_t last = setOfPose(history.after, pose);
        QCOMPARE(levels.size(), last + 1);
        for (std::size_t i = 0; i <= last; ++i) {
            QCOMPARE(levels[i].reference, history.after[i].firstPose - 1);
            QCOMPARE(levels[i].rule, history.after[i].rule);
        }
        QCOMPARE(levels.back().pose, pose);
    }
}

void TestPoseHistoryPlan::refusesPosesWithoutSetsAndBadSets()
{
    const PoseHistorySets afterOnly{2, sets("3:confluent"), {}};
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)planPoseHistory(afterOnly, std::nullopt, 1));
    try {
        (void)poseHistoryLevels(afterOnly, 1);
        QFAIL("a pose before the rest pose without sets there was accepted");
    } catch (const std::invalid_argument& e) {
        QVERIFY2(std::string(e.what()).find("before the rest pose 2") != std::string::npos, e.what());
    }
    const PoseHistorySets gap{0, sets("2:confluent"), {}};
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)poseHistoryLevels(gap, 3));
    const PoseHistorySets unordered{0, sets("1:confluent,4:additive,3:additive"), {}};
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)poseHistoryLevels(unordered, 2));
}

QTEST_APPLESS_MAIN(TestPoseHistoryPlan)
#include "tst_pose_history_plan.moc"
