// The description of a user-facing parameter (core/util/parameter_spec.h): which values
// each kind accepts, how values are spelt and printed, the generated range and help
// texts, the programmer's check, and the self-check every table runs at compile time —
// here also at run time over the core tables of skeleton, skinning, segmentation and
// inspection.
#include "core/animation/segmentation_parameters.h"
#include "core/skeleton/skeleton_parameters.h"
#include "core/skinning/skinning_parameters.h"
#include "core/trim/inspect_parameters.h"
#include "core/util/parameter_spec.h"
#include "core/util/worker_threads_parameter.h"

#include <QtTest>

#include <array>
#include <limits>
#include <stdexcept>

using namespace trimlab;

namespace {

constexpr ParameterSpec kCount{
    .id = "count",
    .flag = "count",
    .settingsKey = "test/count",
    .kind = ParameterKind::Integer,
    .min = 0,
    .max = 64,
    .defaultValue = 0,
    .unit = "MB",
    .help = "How many",
    .minMeaning = "none",
};

constexpr ParameterSpec kScale{
    .id = "scale",
    .flag = "scale",
    .settingsKey = "",
    .kind = ParameterKind::Real,
    .min = 0.001,
    .max = 0.5,
    .defaultValue = 0.25,
    .help = "How large",
};

enum class Colour { Red = 3, Green = 5, Blue = 7 };

constexpr ChoiceValue kColours[] = {
    {"red", int(Colour::Red), "Red"},
    {"green", int(Colour::Green), "Green"},
    {"blue", int(Colour::Blue), "Blue", false},
};

constexpr ParameterSpec kColour{
    .id = "colour",
    .flag = "colour",
    .settingsKey = "",
    .kind = ParameterKind::Choice,
    .defaultValue = int(Colour::Green),
    .help = "Which colour",
    .choices = kColours,
};

constexpr ParameterSpec kSwitch{
    .id = "switch",
    .flag = "switch",
    .settingsKey = "",
    .kind = ParameterKind::Boolean,
    .min = 0,
    .max = 1,
    .defaultValue = 1,
    .help = "Whether",
    .required = false,
};

// Rows that contradict themselves, which a table's static_assert refuses.
constexpr ParameterSpec kDefaultOutside{
    .id = "a", .kind = ParameterKind::Integer, .min = 1, .max = 4, .defaultValue = 5, .help = "x"};
constexpr ParameterSpec kFractionalInteger{
    .id = "b", .kind = ParameterKind::Integer, .min = 0, .max = 4.5, .defaultValue = 1, .help = "x"};
constexpr ParameterSpec kInverted{
    .id = "c", .kind = ParameterKind::Real, .min = 2, .max = 1, .defaultValue = 1.5, .help = "x"};
constexpr ParameterSpec kUnknownDefaultChoice{
    .id = "d", .kind = ParameterKind::Choice, .defaultValue = 4, .help = "x", .choices = kColours};
constexpr ParameterSpec kNoHelp{.id = "e", .kind = ParameterKind::Real, .min = 0, .max = 1, .defaultValue = 0};
static_assert(isWellFormed(kCount) && isWellFormed(kScale) && isWellFormed(kColour) && isWellFormed(kSwitch));
static_assert(!isWellFormed(kDefaultOutside) && !isWellFormed(kFractionalInteger) && !isWellFormed(kInverted) &&
              !isWellFormed(kUnknownDefaultChoice) && !isWellFormed(kNoHelp));
constexpr std::array<const ParameterSpec*, 2> kSameFlagTwice{&kCount, &kCount};
static_assert(!isWellFormedTable(kSameFlagTwice));

} // namespace

class TestParameterSpec : public QObject {
    Q_OBJECT
private slots:
    void acceptsTheValuesOfItsKind();
    void parsesTheSpellingsOfItsKind();
    void printsValuesAsTheyAreSpelt();
    void generatesRangeAndHelp();
    void refusesProgrammersValues();
    void coreTablesAreWellFormedAndMatchTheirStructs();
    void workerThreadsRowIsTheSameEverywhere();
};

void TestParameterSpec::acceptsTheValuesOfItsKind()
{
    QVERIFY(acceptsValue(kCount, 0) && acceptsValue(kCount, 64) && acceptsValue(kCount, 17));
    QVERIFY(!acceptsValue(kCount, -1) && !acceptsValue(kCount, 65) && !acceptsValue(kCount, 2.5));
    QVERIFY(acceptsValue(kScale, 0.001) && acceptsValue(kScale, 0.5) && acceptsValue(kScale, 0.3));
    QVERIFY(!acceptsValue(kScale, 0.0009) && !acceptsValue(kScale, 0.50001));
    QVERIFY(!acceptsValue(kScale, std::numeric_limits<double>::quiet_NaN()));
    QVERIFY(!acceptsValue(kScale, std::numeric_limits<double>::infinity()));
    QVERIFY(acceptsValue(kColour, 3) && acceptsValue(kColour, 7) && !acceptsValue(kColour, 4));
    QVERIFY(acceptsValue(kSwitch, 0) && acceptsValue(kSwitch, 1) && !acceptsValue(kSwitch, 0.5));
}

void TestParameterSpec::parsesTheSpellingsOfItsKind()
{
    QCOMPARE(parseParameterValue(kCount, "12"), std::optional<double>(12));
    QCOMPARE(parseParameterValue(kCount, "-3"), std::optional<double>(-3)); // the range is checked apart
    QCOMPARE(parseParameterValue(kCount, "1.5"), std::nullopt);
    QCOMPARE(parseParameterValue(kCount, "12x"), std::nullopt);
    QCOMPARE(parseParameterValue(kCount, ""), std::nullopt);
    QCOMPARE(parseParameterValue(kScale, "0.25"), std::optional<double>(0.25));
    QCOMPARE(parseParameterValue(kScale, "+2.5e-1"), std::optional<double>(0.25));
    QCOMPARE(parseParameterValue(kScale, "nan"), std::nullopt);
    QCOMPARE(parseParameterValue(kScale, "inf"), std::nullopt);
    QCOMPARE(parseParameterValue(kScale, "0.25 "), std::nullopt);
    QCOMPARE(parseParameterValue(kColour, "red"), std::optional<double>(3));
    QCOMPARE(parseParameterValue(kColour, "blue"), std::optional<double>(7)); // the GUI's, still a name
    QCOMPARE(parseParameterValue(kColour, "Red"), std::nullopt);
    for (const char* yes : {"on", "true", "yes", "1"})
        QCOMPARE(parseParameterValue(kSwitch, yes), std::optional<double>(1));
    for (const char* no : {"off", "false", "no", "0"})
        QCOMPARE(parseParameterValue(kSwitch, no), std::optional<double>(0));
    QCOMPARE(parseParameterValue(kSwitch, "maybe"), std::nullopt);
}

void TestParameterSpec::printsValuesAsTheyAreSpelt()
{
    QCOMPARE(formatParameterValue(kCount, 1048576), std::string("1048576"));
    QCOMPARE(formatParameterValue(kScale, 0.001), std::string("0.001"));
    QCOMPARE(formatParameterValue(kScale, 1e7), std::string("10000000"));
    QCOMPARE(formatParameterValue(kScale, 1.0 / 3.0), std::string("0.3333333333333333"));
    QCOMPARE(formatParameterValue(kColour, 5), std::string("green"));
    QCOMPARE(formatParameterValue(kColour, 6), std::string("?"));
    QCOMPARE(formatParameterValue(kSwitch, 1), std::string("on"));
    // Every printed value reads back as itself.
    for (const double value : {0.1, 1e-6, 0.04, 2048.0, 1.0 / 7.0})
        QCOMPARE(parseParameterValue(kScale, formatParameterValue(kScale, value)), std::optional<double>(value));
}

void TestParameterSpec::generatesRangeAndHelp()
{
    QCOMPARE(parameterRangeText(kCount), std::string("0 to 64"));
    QCOMPARE(parameterRangeText(kScale), std::string("0.001 to 0.5"));
    QCOMPARE(parameterRangeText(kColour), std::string("red or green")); // blue is the GUI's alone
    QCOMPARE(parameterRangeText(kSwitch), std::string("on or off"));
    QCOMPARE(parameterHelpText(kCount), std::string("How many (0 to 64 MB; 0 = none). Default: 0 (none)."));
    QCOMPARE(parameterHelpText(kScale), std::string("How large (0.001 to 0.5). Default: 0.25."));
    QCOMPARE(parameterHelpText(kColour), std::string("Which colour (red or green). Default: green."));
    QCOMPARE(parameterHelpText(kSwitch), std::string("Whether (on or off). Default: on."));
    ParameterSpec required = kScale;
    required.required = true;
    QCOMPARE(parameterHelpText(required), std::string("How large (0.001 to 0.5). Required."));
    ParameterSpec described = kCount;
    described.defaultText = "the last";
    QCOMPARE(parameterHelpText(described), std::string("How many (0 to 64 MB; 0 = none). Default: the last."));
    QCOMPARE(findChoice(kColour, "green"), &kColours[1]);
    QCOMPARE(findChoice(kColour, "grey"), nullptr);
    QCOMPARE(choiceWithValue(kColour, 7), &kColours[2]);
}

void TestParameterSpec::refusesProgrammersValues()
{
    requireParameterValue(kCount, 64);
    try {
        requireParameterValue(kCount, 65);
        QFAIL("no exception");
    } catch (const std::invalid_argument& e) {
        QCOMPARE(std::string(e.what()), std::string("count must be 0 to 64, got 65"));
    }
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, requireParameterValue(kColour, 4));
}

void TestParameterSpec::coreTablesAreWellFormedAndMatchTheirStructs()
{
    for (const auto table : {std::span<const ParameterSpec* const>(skeleton_parameters::kTable),
                             std::span<const ParameterSpec* const>(skinning_parameters::kTable),
                             std::span<const ParameterSpec* const>(segmentation_parameters::kTable),
                             std::span<const ParameterSpec* const>(inspect_parameters::kTable)}) {
        QVERIFY(isWellFormedTable(table));
        for (const ParameterSpec* spec : table) {
            QVERIFY2(acceptsValue(*spec, spec->defaultValue), spec->id.data());
            QVERIFY2(parameterHelpText(*spec).find(parameterRangeText(*spec)) != std::string::npos, spec->id.data());
        }
    }
}

// Every operation's "threads" row has one flag, one limit and 0 meaning every core; only
// the settings key and the help line differ.
void TestParameterSpec::workerThreadsRowIsTheSameEverywhere()
{
    constexpr ParameterSpec threads = workerThreadsParameter("test/threads", "Worker threads");
    static_assert(isWellFormed(threads));
    QCOMPARE(std::string(threads.flag), std::string("threads"));
    QCOMPARE(std::string(threads.settingsKey), std::string("test/threads"));
    QVERIFY(acceptsValue(threads, 0) && acceptsValue(threads, kMaxWorkerThreads));
    QVERIFY(!acceptsValue(threads, -1) && !acceptsValue(threads, kMaxWorkerThreads + 1));
    QCOMPARE(parameterHelpText(threads),
             std::string("Worker threads (0 to 1024; 0 = all cores). Default: 0 (all cores)."));
}

QTEST_GUILESS_MAIN(TestParameterSpec)
#include "tst_parameter_spec.moc"
