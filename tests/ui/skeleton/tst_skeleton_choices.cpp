// Which changes of the Skeleton panel's choices need a new contraction
// (SkeletonChoices::needsContraction, ui/skeleton/skeleton_choices.h): every option of
// stages A–C — each field of the contraction, the simplification and the refinement,
// the experimental ones too (medial attraction, branch recovery, chain routing) — and
// none of the selection's node count and root, the heat constant or the posing.
#include "ui/skeleton/skeleton_choices.h"

#include <QtTest>

#include <functional>
#include <utility>
#include <vector>

using namespace trimlab;
using namespace trimlab::ui;

namespace {

using Change = std::pair<const char*, std::function<void(SkeletonChoices&)>>;

std::vector<Change> curveChanges()
{
    return {
        {"initialContractionWeight", [](SkeletonChoices& c) { c.extraction.contraction.initialContractionWeight = 3; }},
        {"initialAttractionWeight", [](SkeletonChoices& c) { c.extraction.contraction.initialAttractionWeight = 2; }},
        {"contractionGrowth", [](SkeletonChoices& c) { c.extraction.contraction.contractionGrowth = 3; }},
        {"maxContractionWeight", [](SkeletonChoices& c) { c.extraction.contraction.maxContractionWeight = 7; }},
        {"maxAttractionWeight", [](SkeletonChoices& c) { c.extraction.contraction.maxAttractionWeight = 7; }},
        {"minAngleDegrees", [](SkeletonChoices& c) { c.extraction.contraction.minAngleDegrees = 2; }},
        {"minAreaRatio", [](SkeletonChoices& c) { c.extraction.contraction.minAreaRatio = 0.5; }},
        {"minAreaDecrease", [](SkeletonChoices& c) { c.extraction.contraction.minAreaDecrease = 0.5; }},
        {"collapseFraction", [](SkeletonChoices& c) { c.extraction.contraction.collapseFraction = 0.01; }},
        {"inputCollapseFraction", [](SkeletonChoices& c) { c.extraction.contraction.inputCollapseFraction = 0.01; }},
        {"ordering", [](SkeletonChoices& c) { c.extraction.contraction.ordering = SparseOrdering::Amd; }},
        {"backend", [](SkeletonChoices& c) { c.extraction.contraction.backend = SparseBackend::EigenSimplicialLdlt; }},
        {"maxIterations", [](SkeletonChoices& c) { c.extraction.contraction.maxIterations = 3; }},
        {"medialWeight", [](SkeletonChoices& c) { c.extraction.contraction.medialWeight = 1; }},
        {"medialPoints",
         [](SkeletonChoices& c) { c.extraction.contraction.medialPoints = MedialPoints::ShrinkingBalls; }},
        {"preCollapseFraction", [](SkeletonChoices& c) { c.extraction.simplification.preCollapseFraction = 0.01; }},
        {"shapeWeight", [](SkeletonChoices& c) { c.extraction.simplification.shapeWeight = 2; }},
        {"samplingWeight", [](SkeletonChoices& c) { c.extraction.simplification.samplingWeight = 2; }},
        {"refine", [](SkeletonChoices& c) { c.extraction.refine = false; }},
        {"resampleFraction", [](SkeletonChoices& c) { c.extraction.resampleFraction = 0.5; }},
        {"centre", [](SkeletonChoices& c) { c.extraction.centre = false; }},
        {"recoverBranches", [](SkeletonChoices& c) { c.extraction.recoverBranches = false; }},
        {"routeChains", [](SkeletonChoices& c) { c.extraction.routeChains = false; }},
    };
}

std::vector<Change> rigChanges()
{
    return {
        {"targetNodes", [](SkeletonChoices& c) { c.extraction.targetNodes = 25; }},
        {"rootJoint", [](SkeletonChoices& c) { c.extraction.rootJoint = 4; }},
        {"heatConstant", [](SkeletonChoices& c) { c.heatConstant = 0.22; }},
        {"skinning", [](SkeletonChoices& c) { c.skinning = SkinningMethod::Dqs; }},
    };
}

} // namespace

class TestSkeletonChoices : public QObject {
    Q_OBJECT
private slots:
    void everyCurveOptionNeedsAContraction_data();
    void everyCurveOptionNeedsAContraction();
    void theRigAloneNeedsNone();
};

void TestSkeletonChoices::everyCurveOptionNeedsAContraction_data()
{
    QTest::addColumn<int>("change");
    const std::vector<Change> changes = curveChanges();
    for (std::size_t i = 0; i < changes.size(); ++i)
        QTest::newRow(changes[i].first) << int(i);
}

void TestSkeletonChoices::everyCurveOptionNeedsAContraction()
{
    QFETCH(int, change);
    const SkeletonChoices before;
    SkeletonChoices after;
    curveChanges()[std::size_t(change)].second(after);
    QVERIFY(!(before == after));
    QVERIFY(before.needsContraction(after));
    QVERIFY(after.needsContraction(before));
    // Together with a new node count it still needs one.
    after.extraction.targetNodes = 22;
    QVERIFY(before.needsContraction(after));
}

void TestSkeletonChoices::theRigAloneNeedsNone()
{
    const SkeletonChoices before;
    QVERIFY(!before.needsContraction(before));
    SkeletonChoices after;
    for (const Change& change : rigChanges()) {
        change.second(after);
        QVERIFY2(!before.needsContraction(after), change.first);
    }
    QVERIFY(!(before == after));
}

QTEST_GUILESS_MAIN(TestSkeletonChoices)
#include "tst_skeleton_choices.moc"
