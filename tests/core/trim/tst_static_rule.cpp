// Table-driven test of the static rules (thesis 8.1.1 and the nonzero, negative and
// threshold rules) over w in [-8, 8].
#include "core/trim/static_rule.h"

#include <QtTest>

using namespace trimlab;

class TestStaticRule : public QObject {
    Q_OBJECT
private slots:
    void table_data();
    void table();
    void trimBoundaryAlternatesAtCrossings();
    void namesRoundTrip();
    void orientationInvariance();
    void shaderCodePacksKindAndThreshold();
};

void TestStaticRule::table_data()
{
    QTest::addColumn<int>("w");
    QTest::addColumn<bool>("parity");
    QTest::addColumn<bool>("positive");
    QTest::addColumn<bool>("alternating");
    QTest::addColumn<bool>("nonzero");
    QTest::addColumn<bool>("negative");
    QTest::addColumn<bool>("atLeast2");
    QTest::addColumn<bool>("absAtLeast3");
    // Written out by hand from the definitions, not generated from the code under test:
    // parity: w odd; positive index: w >= 1; alternating border: w mod 4 in {1, 2};
    // nonzero: w != 0; negative: w < 0; w >= 2; |w| >= 3.
    struct Row {
        int w;
        bool parity, positive, alternating, nonzero, negative, atLeast2, absAtLeast3;
    };
    const Row rows[] = {
        {-8, false, false, false, true, true, false, true},   {-7, true, false, true, true, true, false, true},
        {-6, false, false, true, true, true, false, true},    {-5, true, false, false, true, true, false, true},
        {-4, false, false, false, true, true, false, true},   {-3, true, false, true, true, true, false, true},
        {-2, false, false, true, true, true, false, false},   {-1, true, false, false, true, true, false, false},
        {0, false, false, false, false, false, false, false}, {1, true, true, true, true, false, false, false},
        {2, false, true, true, true, false, true, false},     {3, true, true, false, true, false, true, true},
        {4, false, true, false, true, false, true, true},     {5, true, true, true, true, false, true, true},
        {6, false, true, true, true, false, true, true},      {7, true, true, false, true, false, true, true},
        {8, false, true, false, true, false, true, true},
    };
    for (const Row& r : rows)
        QTest::newRow(qPrintable(QString("w=%1").arg(r.w)))
            << r.w << r.parity << r.positive << r.alternating << r.nonzero << r.negative << r.atLeast2 << r.absAtLeast3;
}

void TestStaticRule::table()
{
    QFETCH(int, w);
    QFETCH(bool, parity);
    QFETCH(bool, positive);
    QFETCH(bool, alternating);
    QFETCH(bool, nonzero);
    QFETCH(bool, negative);
    QFETCH(bool, atLeast2);
    QFETCH(bool, absAtLeast3);
    QCOMPARE(isInterior(StaticRule::Parity, w), parity);
    QCOMPARE(isInterior(StaticRule::PositiveIndex, w), positive);
    QCOMPARE(isInterior(StaticRule::AlternatingBorder, w), alternating);
    QCOMPARE(isInterior(StaticRule::Nonzero, w), nonzero);
    QCOMPARE(isInterior(StaticRule::Negative, w), negative);
    QCOMPARE(isInterior(StaticRule::atLeast(2), w), atLeast2);
    QCOMPARE(isInterior(StaticRule::absAtLeast(3), w), absAtLeast3);
}

// Theorem 8.1: crossing a self-crossing surface changes w by +-1 on both sides of a face,
// and the alternating border rule flips whether the face is trim.
void TestStaticRule::trimBoundaryAlternatesAtCrossings()
{
    for (int w = -8; w <= 8; ++w) {
        for (int step : {+1, -1}) {
            const bool before = isTrimBoundary(StaticRule::AlternatingBorder, w, w + 1);
            const bool after = isTrimBoundary(StaticRule::AlternatingBorder, w + step, w + step + 1);
            QVERIFY2(before != after, qPrintable(QString("w=%1 step=%2").arg(w).arg(step)));
        }
        // Parity makes every fragment a trim fragment: it never trims a clean crossing.
        QVERIFY(isTrimBoundary(StaticRule::Parity, w, w + 1));
    }
}

void TestStaticRule::namesRoundTrip()
{
    for (StaticRule r : {StaticRule::Parity, StaticRule::PositiveIndex, StaticRule::AlternatingBorder,
                         StaticRule::Nonzero, StaticRule::Negative, StaticRule::atLeast(2), StaticRule::atLeast(17),
                         StaticRule::absAtLeast(2), StaticRule::absAtLeast(StaticRule::kMaxThreshold)})
        QCOMPARE(parseStaticRule(ruleName(r)), std::optional<StaticRule>(r));
    QCOMPARE(ruleName(StaticRule::atLeast(3)), std::string("w>=3"));
    QCOMPARE(ruleName(StaticRule::absAtLeast(4)), std::string("|w|>=4"));
    QCOMPARE(parseStaticRule("positive"), std::optional<StaticRule>(StaticRule::PositiveIndex));
    QCOMPARE(parseStaticRule("at-least-5"), std::optional<StaticRule>(StaticRule::atLeast(5)));
    QCOMPARE(parseStaticRule("abs-at-least-2"), std::optional<StaticRule>(StaticRule::absAtLeast(2)));
    // K = 1 is the same rule as positive index / nonzero, and keeps their name.
    QCOMPARE(parseStaticRule("w>=1"), std::optional<StaticRule>(StaticRule::PositiveIndex));
    QCOMPARE(parseStaticRule("|w|>=1"), std::optional<StaticRule>(StaticRule::Nonzero));
    for (const char* bad : {"winding", "", "w>=", "w>=0", "w>=-2", "w>=abc", "w>=2x", "w>= 2", "|w|>=1025",
                            "w>=99999999999", "at-least-", "NONZERO"})
        QVERIFY2(!parseStaticRule(bad).has_value(), bad);
}

// Reversing every orientation maps w to -w: the orientation-invariant rules keep the same
// cells, the others do not.
void TestStaticRule::orientationInvariance()
{
    for (StaticRule r :
         {StaticRule::Parity, StaticRule::PositiveIndex, StaticRule::AlternatingBorder, StaticRule::Nonzero,
          StaticRule::Negative, StaticRule::atLeast(2), StaticRule::absAtLeast(2)}) {
        bool symmetric = true;
        for (int w = -8; w <= 8; ++w)
            symmetric = symmetric && isInterior(r, w) == isInterior(r, -w);
        QVERIFY2(symmetric == r.orientationInvariant(), ruleName(r).c_str());
    }
}

// The shaders decode the kind from the low four bits and K above them.
void TestStaticRule::shaderCodePacksKindAndThreshold()
{
    QCOMPARE(shaderRuleCode(StaticRule::Parity), 0);
    QCOMPARE(shaderRuleCode(StaticRule::AlternatingBorder), 2);
    QCOMPARE(shaderRuleCode(StaticRule::atLeast(3)) & 15, int(StaticRule::Kind::AtLeast));
    QCOMPARE(shaderRuleCode(StaticRule::atLeast(3)) >> 4, 3);
    QCOMPARE(shaderRuleCode(StaticRule::absAtLeast(StaticRule::kMaxThreshold)) >> 4, StaticRule::kMaxThreshold);
}

QTEST_APPLESS_MAIN(TestStaticRule)
#include "tst_static_rule.moc"
