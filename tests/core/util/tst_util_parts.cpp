// The small utilities every area uses: comma-separated number lists, the cancel and
// progress protocol of long operations, disjoint sets, bit-pattern equality, and text from
// files made safe to print.
#include "core/util/float_bits.h"
#include "core/util/parse_numbers.h"
#include "core/util/printable_text.h"
#include "core/util/task_control.h"
#include "core/util/union_find.h"

#include <QtTest>

#include <cmath>
#include <limits>
#include <stop_token>
#include <string>
#include <vector>

using namespace trimlab;

class TestUtilParts : public QObject {
    Q_OBJECT

private slots:
    void printableTextEscapesWhatATerminalWouldActOn()
    {
        // An escape sequence that would turn the terminal red and retitle it, shown instead.
        QCOMPARE(printableText("bad token '\x1b[31mX\x1b]0;owned\x07'"),
                 std::string("bad token '\\x1b[31mX\\x1b]0;owned\\x07'"));
        QCOMPARE(printableText("a\rb\x7f\v"), std::string("a\\rb\\x7f\\v"));
        // Line feed, tab, backslash and ordinary multi-byte text are kept.
        QCOMPARE(printableText("line 1\n\tnode \"caf\xc3\xa9 \xe2\x86\x92 \xf0\x9f\x90\x8e\" C:\\x"),
                 std::string("line 1\n\tnode \"caf\xc3\xa9 \xe2\x86\x92 \xf0\x9f\x90\x8e\" C:\\x"));
        // C1 controls (U+009B is a one-character CSI) and bidirectional overrides.
        QCOMPARE(printableText("x\xc2\x9b"
                               "31m"),
                 std::string("x\\u009b31m"));
        QCOMPARE(printableText("evil\xe2\x80\xaegpj.obj"), std::string("evil\\u202egpj.obj"));
        QCOMPARE(printableText("\xe2\x81\xa6"), std::string("\\u2066"));
        // Bytes outside well-formed UTF-8: a stray continuation, a cut sequence, an overlong
        // form, a surrogate, a lead byte above U+10FFFF.
        QCOMPARE(printableText("\x80"), std::string("\\x80"));
        QCOMPARE(printableText("\xe2\x86"), std::string("\\xe2\\x86"));
        QCOMPARE(printableText("\xc0\xaf"), std::string("\\xc0\\xaf"));
        QCOMPARE(printableText("\xed\xa0\x80"), std::string("\\xed\\xa0\\x80"));
        QCOMPARE(printableText("\xf5\x80\x80\x80"), std::string("\\xf5\\x80\\x80\\x80"));
        QCOMPARE(printableText(std::string_view("a\0b", 3)), std::string("a\\x00b"));
        QCOMPARE(printableText(""), std::string());
    }

    void numberListsParseExactlyTheCount()
    {
        std::string error;
        QCOMPARE(parseNumberList("1,2.5,-3e2", 3, &error), std::optional(std::vector<double>{1.0, 2.5, -300.0}));
        QCOMPARE(parseNumberList("7", 1, nullptr), std::optional(std::vector<double>{7.0}));

        QVERIFY(!parseNumberList("1,2", 3, &error));
        QCOMPARE(error, std::string("expected 3 comma-separated numbers, got 2 in '1,2'"));
        QVERIFY(!parseNumberList("1,,2", 3, &error));
        QCOMPARE(error, std::string("'' is not a finite number in '1,,2'"));
        QVERIFY(!parseNumberList("1,x,2", 3, &error));
        QCOMPARE(error, std::string("'x' is not a finite number in '1,x,2'"));
        QVERIFY(!parseNumberList("1, 2", 2, &error)); // no spaces
        QVERIFY(!parseNumberList("1,inf", 2, &error));
        QVERIFY(!parseNumberList("1,nan", 2, nullptr));
        QVERIFY(!parseNumberList("", 1, &error));
    }

    void taskControlReportsAndCancels()
    {
        const TaskControl silent;
        silent.report("load", 1, 2); // no callback: nothing happens
        silent.throwIfCancelled();

        std::vector<std::string> seen;
        std::stop_source source;
        TaskControl control;
        control.progress = [&](const TaskProgress& p) {
            seen.push_back(std::string(p.stage) + " " + std::to_string(p.done) + "/" + std::to_string(p.total));
        };
        control.stop = source.get_token();
        control.report("features", 0, 3);
        control.report("features", 3, 3);
        QCOMPARE(seen, (std::vector<std::string>{"features 0/3", "features 3/3"}));
        control.throwIfCancelled();
        source.request_stop();
        QVERIFY_THROWS_EXCEPTION(OperationCancelled, control.throwIfCancelled());
        try {
            control.throwIfCancelled();
        } catch (const OperationCancelled& e) {
            QCOMPARE(std::string(e.what()), std::string("the operation was cancelled"));
        }
    }

    void unionFindJoinsSets()
    {
        UnionFind sets(6);
        for (std::size_t i = 0; i < 6; ++i)
            QCOMPARE(sets.find(i), i);
        sets.unite(0, 1);
        sets.unite(2, 3);
        sets.unite(1, 3);
        QCOMPARE(sets.find(0), sets.find(3));
        QCOMPARE(sets.find(2), sets.find(1));
        QVERIFY(sets.find(4) != sets.find(0));
        QVERIFY(sets.find(4) != sets.find(5));
        sets.unite(3, 3); // a set with itself stays as it is
        QCOMPARE(sets.find(0), sets.find(2));
    }

    // Bits, not values: −0 differs from 0 and a NaN equals itself.
    void sameBitsComparesPatterns()
    {
        const float nan = std::numeric_limits<float>::quiet_NaN();
        QVERIFY(sameBits(glm::vec3(1, 2, 3), glm::vec3(1, 2, 3)));
        QVERIFY(!sameBits(glm::vec3(0.0f, 1, 1), glm::vec3(-0.0f, 1, 1)));
        QVERIFY(sameBits(glm::vec3(nan, 1, 1), glm::vec3(nan, 1, 1)));
        QVERIFY(!sameBits(glm::vec3(1, 2, 3), glm::vec3(1, 2, std::nextafter(3.0f, 4.0f))));
        QVERIFY(sameBits(glm::dvec3(0.1, 0.2, 0.3), glm::dvec3(0.1, 0.2, 0.3)));
        QVERIFY(!sameBits(glm::dvec3(0.0, 0, 0), glm::dvec3(-0.0, 0, 0)));
        QVERIFY(!sameBits(glm::dvec3(0.1, 0.2, 0.3), glm::dvec3(0.1, 0.2, std::nextafter(0.3, 1.0))));
    }
};

QTEST_APPLESS_MAIN(TestUtilParts)
#include "tst_util_parts.moc"
