// Table-driven test of the static rules of thesis 8.1.1 over w in [-8, 8].
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
};

void TestStaticRule::table_data()
{
    QTest::addColumn<int>("w");
    QTest::addColumn<bool>("parity");
    QTest::addColumn<bool>("positive");
    QTest::addColumn<bool>("alternating");
    // Written out by hand from the definitions, not generated from the code under test:
    // parity: w odd; positive index: w >= 1; alternating border: w mod 4 in {1, 2}.
    struct Row { int w; bool parity, positive, alternating; };
    const Row rows[] = {
        {-8, false, false, false}, {-7, true, false, true},  {-6, false, false, true},
        {-5, true, false, false},  {-4, false, false, false}, {-3, true, false, true},
        {-2, false, false, true},  {-1, true, false, false}, {0, false, false, false},
        {1, true, true, true},     {2, false, true, true},    {3, true, true, false},
        {4, false, true, false},   {5, true, true, true},     {6, false, true, true},
        {7, true, true, false},    {8, false, true, false},
    };
    for (const Row& r : rows)
        QTest::newRow(qPrintable(QString("w=%1").arg(r.w))) << r.w << r.parity << r.positive << r.alternating;
}

void TestStaticRule::table()
{
    QFETCH(int, w);
    QFETCH(bool, parity);
    QFETCH(bool, positive);
    QFETCH(bool, alternating);
    QCOMPARE(isInterior(StaticRule::Parity, w), parity);
    QCOMPARE(isInterior(StaticRule::PositiveIndex, w), positive);
    QCOMPARE(isInterior(StaticRule::AlternatingBorder, w), alternating);
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
    for (StaticRule r : {StaticRule::Parity, StaticRule::PositiveIndex, StaticRule::AlternatingBorder})
        QCOMPARE(parseStaticRule(ruleName(r)), std::optional<StaticRule>(r));
    QCOMPARE(parseStaticRule("positive"), std::optional<StaticRule>(StaticRule::PositiveIndex));
    QVERIFY(!parseStaticRule("winding").has_value());
    QVERIFY(!parseStaticRule("").has_value());
}

QTEST_APPLESS_MAIN(TestStaticRule)
#include "tst_static_rule.moc"
