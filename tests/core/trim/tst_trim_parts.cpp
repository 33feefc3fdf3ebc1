// The value types of the trim: hits and the order a ray walks them, the classification of
// a ray's fragments, the characterization bit vector, and the settings every renderer
// reads (clipping planes, per-object rules, caps, X-ray and their stable names).
#include "core/trim/classified_fragment.h"
#include "core/trim/inspect_settings.h"
#include "core/trim/partition_characterization.h"
#include "core/trim/ray_hit.h"
#include "core/trim/trim_settings.h"

#include <QtTest>

#include <algorithm>
#include <vector>

using namespace trimlab;

namespace {

RayHit hit(double t, int facing, int primitive = 0, int object = 0)
{
    return RayHit{t, object, primitive, facing, 0.0, 0.0};
}

std::vector<bool> keptOf(const std::vector<ClassifiedFragment>& fragments)
{
    std::vector<bool> kept;
    for (const ClassifiedFragment& f : fragments)
        kept.push_back(f.kept());
    return kept;
}

} // namespace

class TestTrimParts : public QObject {
    Q_OBJECT

private slots:
    // By t, then object, then primitive: coincident surfaces resolve the same way always.
    void walkOrderBreaksTiesByObjectThenPrimitive()
    {
        std::vector<RayHit> hits = {hit(2.0, 1, 0, 0), hit(1.0, 1, 5, 1), hit(1.0, 1, 7, 0), hit(1.0, -1, 3, 0)};
        std::sort(hits.begin(), hits.end(), walkOrder);
        QCOMPARE(hits[0].primitiveId, 3);
        QCOMPARE(hits[1].primitiveId, 7);
        QCOMPARE(hits[2].objectId, 1);
        QCOMPARE(hits[3].t, 2.0);
        QVERIFY(!walkOrder(hits[0], hits[0]));
    }

    // Two nested spheres seen from outside: windings 0 | 1 | 2 | 1 | 0 from the eye.
    // Every fragment gets the windings on its two sides; the rule decides which are kept.
    void staticFragmentsCarryTheWindingsOfBothSides()
    {
        const std::vector<RayHit> hits = {hit(1.0, 1, 10), hit(2.0, 1, 11), hit(3.0, -1, 12), hit(4.0, -1, 13)};
        const std::vector<ClassifiedFragment> parity = staticRayFragments(hits, StaticRule::Parity);
        QCOMPARE(parity.size(), std::size_t(4));
        const int front[] = {0, 1, 2, 1}, back[] = {1, 2, 1, 0};
        for (std::size_t i = 0; i < 4; ++i) {
            QCOMPARE(parity[i].triangle, std::uint32_t(10 + i));
            QCOMPARE(parity[i].depth, double(i + 1));
            QCOMPARE(parity[i].windingFront, front[i]);
            QCOMPARE(parity[i].windingBack, back[i]);
            QCOMPARE(parity[i].interiorFront, front[i] % 2 == 1);
            QCOMPARE(parity[i].interiorBack, back[i] % 2 == 1);
        }
        QCOMPARE(keptOf(parity), (std::vector<bool>{true, true, true, true}));
        QCOMPARE(keptOf(staticRayFragments(hits, StaticRule::AlternatingBorder)),
                 (std::vector<bool>{true, false, false, true}));
        QCOMPARE(keptOf(staticRayFragments(hits, StaticRule::atLeast(2))),
                 (std::vector<bool>{false, true, true, false}));
        QVERIFY(staticRayFragments({}, StaticRule::Parity).empty());
    }

    void characterizationHoldsEveryLayerAndMarksOverflow()
    {
        PartitionCharacterization c;
        for (const int interval : {0, 31, 32, 100, PartitionCharacterization::kLayers - 1})
            c.set(interval, true);
        QVERIFY(c.interior(0) && c.interior(31) && c.interior(32) && c.interior(100));
        QVERIFY(c.interior(PartitionCharacterization::kLayers - 1));
        QVERIFY(!c.interior(1) && !c.interior(33));
        QVERIFY(!c.overflowed);
        c.set(31, false);
        QVERIFY(!c.interior(31) && c.interior(0) && c.interior(32));
        PartitionCharacterization copy = c;
        QCOMPARE(copy, c);
        copy.set(PartitionCharacterization::kLayers, true);
        QVERIFY(copy.overflowed);
        QVERIFY(!copy.interior(PartitionCharacterization::kLayers));
        QVERIFY(!copy.interior(-1));
        QVERIFY(!(copy == c));
        c.set(-1, false);
        QVERIFY(c.overflowed);
    }

    // Plane 0 is `clip`, planes 1.. are moreClips; setClipSet and clipSet round-trip.
    void clipSetRoundTripsThroughTheSettings()
    {
        TrimSettings settings;
        QVERIFY(!settings.clipSet().anyEnabled());
        ClipSet set;
        set.planes[0] = {true, {1, 0, 0}, 0.5};
        set.planes[3] = {true, {0, -1, 0}, 2.0};
        settings.setClipSet(set);
        QCOMPARE(settings.clip, set.planes[0]);
        QCOMPARE(settings.moreClips[2], set.planes[3]);
        QCOMPARE(settings.clipSet(), set);
        QCOMPARE(settings.clipPlane(3), set.planes[3]);
        settings.clipPlane(5).enabled = true;
        QVERIFY(settings.moreClips[4].enabled);
        QCOMPARE(settings.clipSet().enabledCount(), 3);
    }

    void objectRulesCapsAndXrayFollowTheirSwitches()
    {
        TrimSettings settings;
        QCOMPARE(settings.objectRule(0), settings.rule);
        settings.csg.objectRules[1] = StaticRule::Nonzero;
        QCOMPARE(settings.objectRule(1), StaticRule::Nonzero);
        QCOMPARE(settings.objectRule(kMaxCsgOperands), settings.rule); // beyond the operands
        QCOMPARE(settings.objectRule(-1), settings.rule);

        QVERIFY(!settings.perObjectWinding());
        settings.highlight.collisions = true;
        QVERIFY(settings.perObjectWinding() && settings.highlight.any());
        settings.trimEnabled = false;
        QVERIFY(!settings.perObjectWinding());

        settings.trimEnabled = true;
        settings.cap.enabled = true;
        QVERIFY(!settings.capping()); // no plane enabled
        settings.clip.enabled = true;
        QVERIFY(settings.capping());
        settings.trimEnabled = false;
        QVERIFY(!settings.capping());

        QVERIFY(!settings.xray());
        settings.transparency.enabled = true;
        QVERIFY(settings.xray());
        TrimSettings other = settings;
        QCOMPARE(other, settings);
        other.transparency.ghostAlpha = 0.5;
        QVERIFY(!(other == settings));
    }

    void settingNamesRoundTrip()
    {
        for (const CapPattern p : {CapPattern::Hatched, CapPattern::Striped, CapPattern::Solid})
            QCOMPARE(parseCapPattern(capPatternName(p)), std::optional(p));
        QCOMPARE(capPatternName(CapPattern::Striped), std::string_view("striped"));
        QVERIFY(!parseCapPattern("Hatched"));
        QVERIFY(!parseCapPattern(""));
        for (const TrimDisplay d : {TrimDisplay::Opaque, TrimDisplay::Translucent})
            QCOMPARE(parseTrimDisplay(trimDisplayName(d)), std::optional(d));
        QCOMPARE(trimDisplayName(TrimDisplay::Opaque), std::string_view("opaque"));
        QVERIFY(!parseTrimDisplay("ghost"));
    }
};

QTEST_APPLESS_MAIN(TestTrimParts)
#include "tst_trim_parts.moc"
