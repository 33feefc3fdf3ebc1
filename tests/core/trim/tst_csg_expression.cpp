// The CSG expression's text form (parse, print, round trip, errors) and its evaluation on
// inside-bit vectors, against truth tables written out by hand.
#include "core/trim/csg_expression.h"

#include <QtTest>

#include <random>

using namespace trimlab;

namespace {

CsgExpression parsed(const char* text)
{
    std::string error;
    const std::optional<CsgExpression> e = parseCsgExpression(text, &error);
    if (!e)
        qFatal("'%s' did not parse: %s", text, error.c_str());
    return *e;
}

CsgExpression leaf(int id)
{
    return CsgExpression::operand(id);
}

// A random tree over objects 0..7 with 2-3 operands per inner node.
CsgExpression randomTree(std::mt19937& random, int depth)
{
    if (depth == 0 || random() % 3 == 0)
        return leaf(int(random() % kMaxCsgOperands));
    const CsgOperation operations[] = {CsgOperation::Union, CsgOperation::Intersection, CsgOperation::Difference};
    std::vector<CsgExpression> operands;
    const int n = 2 + int(random() % 2);
    for (int i = 0; i < n; ++i)
        operands.push_back(randomTree(random, depth - 1));
    return CsgExpression::combine(operations[random() % 3], operands);
}

} // namespace

class TestCsgExpression : public QObject {
    Q_OBJECT
private slots:
    void parsesIntoTrees();
    void printsCanonically_data();
    void printsCanonically();
    void roundTripsRandomTrees();
    void rejectsBadText_data();
    void rejectsBadText();
    void acceptsDepthUpToTheLimit();
    void evaluates_data();
    void evaluates();
    void truthTableMatchesEvaluation();
    void operandMaskAndMaximum();
};

void TestCsgExpression::parsesIntoTrees()
{
    using Op = CsgOperation;
    QCOMPARE(parsed("3"), leaf(3));
    QCOMPARE(parsed(" 0|1 "), CsgExpression::combine(Op::Union, {leaf(0), leaf(1)}));
    // A chain of one operator is one n-ary node.
    QCOMPARE(parsed("0 | 1 | 2"), CsgExpression::combine(Op::Union, {leaf(0), leaf(1), leaf(2)}));
    QCOMPARE(parsed("0 - 1 - 2"), CsgExpression::combine(Op::Difference, {leaf(0), leaf(1), leaf(2)}));
    // & binds tighter than | and -.
    QCOMPARE(
        parsed("0 | 1 & 2"),
        CsgExpression::combine(Op::Union, {leaf(0), CsgExpression::combine(Op::Intersection, {leaf(1), leaf(2)})}));
    // | and - are left-associative at one level.
    QCOMPARE(parsed("0 | 1 - 2"),
             CsgExpression::combine(Op::Difference, {CsgExpression::combine(Op::Union, {leaf(0), leaf(1)}), leaf(2)}));
    QCOMPARE(parsed("0 - (1 | 2)"),
             CsgExpression::combine(Op::Difference, {leaf(0), CsgExpression::combine(Op::Union, {leaf(1), leaf(2)})}));
    // Parentheses keep a nested node of the same operator.
    QCOMPARE(parsed("(0 & 1) & 2"),
             CsgExpression::combine(Op::Intersection,
                                    {CsgExpression::combine(Op::Intersection, {leaf(0), leaf(1)}), leaf(2)}));
}

void TestCsgExpression::printsCanonically_data()
{
    QTest::addColumn<QString>("input");
    QTest::addColumn<QString>("printed");
    QTest::newRow("leaf") << "7"
                          << "7";
    QTest::newRow("spaces") << "0|1"
                            << "0 | 1";
    QTest::newRow("redundant parentheses") << "((0) | (1 & 2))"
                                           << "0 | 1 & 2";
    QTest::newRow("needed parentheses") << "0 & (1 | 2)"
                                        << "0 & (1 | 2)";
    QTest::newRow("right difference") << "0 - (1 - 2)"
                                      << "0 - (1 - 2)";
    QTest::newRow("left chain") << "(0 | 1) - 2"
                                << "0 | 1 - 2";
    QTest::newRow("same operator kept nested") << "(0 | 1) | 2"
                                               << "(0 | 1) | 2";
    QTest::newRow("tree") << "0 | (1 & ~ 2)"
                          << "";
}

void TestCsgExpression::printsCanonically()
{
    QFETCH(QString, input);
    QFETCH(QString, printed);
    std::string error;
    const auto e = parseCsgExpression(input.toStdString(), &error);
    if (printed.isEmpty()) { // no complement operator
        QVERIFY(!e);
        QVERIFY(error.find("at character") != std::string::npos);
        return;
    }
    QVERIFY2(e, error.c_str());
    QCOMPARE(QString::fromStdString(formatCsgExpression(*e)), printed);
}

void TestCsgExpression::roundTripsRandomTrees()
{
    std::mt19937 random(20140601);
    for (int i = 0; i < 500; ++i) {
        const CsgExpression e = randomTree(random, 4);
        const std::string text = formatCsgExpression(e);
        std::string error;
        const auto back = parseCsgExpression(text, &error);
        QVERIFY2(back, qPrintable(QString::fromStdString(text + ": " + error)));
        QVERIFY2(*back == e, text.c_str());
    }
}

void TestCsgExpression::rejectsBadText_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("message");
    QTest::newRow("empty") << ""
                           << "at character 1: expected an object id";
    QTest::newRow("blank") << "   "
                           << "expected an object id";
    QTest::newRow("dangling operator") << "0 |"
                                       << "expected an object id";
    QTest::newRow("unclosed") << "(0 | 1"
                              << "expected ')'";
    QTest::newRow("extra close") << "0 | 1)"
                                 << "at character 6: unexpected ')'";
    QTest::newRow("id out of range") << "0 | 8"
                                     << "object id 8 is out of range";
    QTest::newRow("huge id") << "123456789"
                             << "out of range";
    QTest::newRow("name") << "a | b"
                          << "at character 1: expected an object id or '(', got 'a'";
    // Hostile lengths and nesting: a clear error, never a stack overflow (each of these
    // crashed the recursive parser or its walks before the limits).
    QTest::newRow("deep parentheses") << QString(2000, QLatin1Char('(')) + "0" + QString(2000, QLatin1Char(')'))
                                      << "parentheses nested more than 64 deep";
    QTest::newRow("100000 parentheses") << QString(100000, QLatin1Char('(')) + "0" + QString(100000, QLatin1Char(')'))
                                        << "200001 characters long; at most 4096";
    QTest::newRow("65 parentheses") << QString(65, QLatin1Char('(')) + "0" + QString(65, QLatin1Char(')'))
                                    << "at character 65: parentheses nested more than 64 deep";
    QString switching = QStringLiteral("0");
    for (int i = 0; i < 1000; ++i)
        switching += i % 2 ? QStringLiteral("|1") : QStringLiteral("-2");
    QTest::newRow("operator switches") << switching << "operators change more than 64 times";
    QTest::newRow("long text") << QString(5000, QLatin1Char(' ')) + "0"
                               << "5001 characters long; at most 4096";
    QTest::newRow("two operands") << "0 1"
                                  << "unexpected '1'";
}

void TestCsgExpression::rejectsBadText()
{
    QFETCH(QString, text);
    QFETCH(QString, message);
    std::string error;
    QVERIFY(!parseCsgExpression(text.toStdString(), &error));
    QVERIFY2(QString::fromStdString(error).contains(message), error.c_str());
}

// The limits are not below what a user may type: 64 parentheses and 64 changes of
// operator parse, and the tree evaluates.
void TestCsgExpression::acceptsDepthUpToTheLimit()
{
    const QString nested = QString(64, QLatin1Char('(')) + "0 | 1" + QString(64, QLatin1Char(')'));
    QVERIFY(evaluateCsg(parsed(qPrintable(nested)), 0b10));
    QString switching = QStringLiteral("0");
    for (int i = 0; i < 64; ++i)
        switching += i % 2 ? QStringLiteral("|1") : QStringLiteral("-1");
    QCOMPARE(evaluateCsg(parsed(qPrintable(switching)), 0b11), true); // ends with "| 1"
}

void TestCsgExpression::evaluates_data()
{
    QTest::addColumn<QString>("expression");
    QTest::addColumn<QString>("table"); // classification of masks 0..7 (bit o: object o inside)
    // Masks: 0=000 1=A 2=B 3=AB 4=C 5=AC 6=BC 7=ABC (A = object 0).
    QTest::newRow("A") << "0"
                       << "01010101";
    QTest::newRow("A|B") << "0 | 1"
                         << "01110111";
    QTest::newRow("A&B") << "0 & 1"
                         << "00010001";
    QTest::newRow("A-B") << "0 - 1"
                         << "01000100";
    QTest::newRow("B-A") << "1 - 0"
                         << "00100010";
    QTest::newRow("A|B|C") << "0 | 1 | 2"
                           << "01111111";
    QTest::newRow("A&B&C") << "0 & 1 & 2"
                           << "00000001";
    QTest::newRow("A-B-C") << "0 - 1 - 2"
                           << "01000000";
    QTest::newRow("A|(B&C)") << "0 | (1 & 2)"
                             << "01010111";
    QTest::newRow("(A|B)-C") << "(0 | 1) - 2"
                             << "01110000";
    QTest::newRow("A-(B-C)") << "0 - (1 - 2)"
                             << "01000101"; // A and not (B and not C)
    QTest::newRow("A&(B|C)") << "0 & (1 | 2)"
                             << "00010101";
}

void TestCsgExpression::evaluates()
{
    QFETCH(QString, expression);
    QFETCH(QString, table);
    const CsgExpression e = parsed(qPrintable(expression));
    for (std::uint32_t mask = 0; mask < 8; ++mask)
        QVERIFY2(evaluateCsg(e, mask) == (table[int(mask)] == QLatin1Char('1')),
                 qPrintable(QString("%1 at mask %2").arg(expression).arg(mask)));
    // Objects the expression does not mention change nothing.
    for (std::uint32_t mask = 0; mask < 8; ++mask)
        QCOMPARE(evaluateCsg(e, mask | 0xF8u), evaluateCsg(e, mask));
}

void TestCsgExpression::truthTableMatchesEvaluation()
{
    std::mt19937 random(7);
    for (int i = 0; i < 50; ++i) {
        const CsgExpression e = randomTree(random, 3);
        const CsgTruthTable table = csgTruthTable(e);
        for (std::uint32_t mask = 0; mask < 256; ++mask)
            QCOMPARE(((table[mask >> 5] >> (mask & 31u)) & 1u) != 0, evaluateCsg(e, mask));
    }
    // Union of everything: only mask 0 is outside.
    const CsgTruthTable all = csgTruthTable(parsed("0|1|2|3|4|5|6|7"));
    QCOMPARE(all[0], 0xFFFFFFFEu);
    for (std::size_t w = 1; w < all.size(); ++w)
        QCOMPARE(all[w], 0xFFFFFFFFu);
}

void TestCsgExpression::operandMaskAndMaximum()
{
    const CsgExpression e = parsed("5 - (1 & 2) | 1");
    QCOMPARE(csgOperandMask(e), (1u << 5) | (1u << 1) | (1u << 2));
    QCOMPARE(csgMaxObjectId(e), 5);
    QCOMPARE(csgMaxObjectId(parsed("0")), 0);
}

QTEST_APPLESS_MAIN(TestCsgExpression)
#include "tst_csg_expression.moc"
