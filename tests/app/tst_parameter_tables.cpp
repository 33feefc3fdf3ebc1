// The command line against the parameter tables: for render, bench, skin, skeleton and
// segment, every flagged row is walked through the real trimlab binary (a child
// process). The row's minimum and maximum (and every choice, both booleans) are accepted
// — the run stops at the verb's next check, which each case arranges to fail cheaply
// (no source, an unknown scene) — and one step below and above the range (an unknown
// name, a non-boolean) is refused with exit code 2 and one line that names the flag and
// the range. The verbs parse their tables before any other check, so one bad value is
// reported as itself. Also: every row of the operations' core tables is on the command
// line unless it is listed here as the GUI's alone, with the reason.
#include "run_trimlab.h"

#include "app/bench_options.h"
#include "app/render_options.h"
#include "app/segment_options.h"
#include "app/skeleton_options.h"
#include "app/skin_options.h"

#include <QRegularExpression>
#include <QtTest>

#include <algorithm>
#include <span>

using namespace trimlab;

using trimlab::test::Run;
using trimlab::test::runTrimlab;

namespace {

/// A verb, its table, and what its parse reports next when only table flags are given.
struct Verb {
    const char* name;
    std::span<const ParameterSpec* const> table;
    QStringList stop;    ///< extra arguments that make the run stop after the table
    QString stopMessage; ///< the error of that stop
};

std::vector<Verb> verbs()
{
    return {
        {"render", app::render_verb_parameters::kTable, {}, "render needs at least one source"},
        {"bench", app::bench_parameters::kTable, {"--scenes", "no-such-scene"}, "unknown scene 'no-such-scene'"},
        {"skin", app::skin_verb_parameters::kTable, {}, "skin needs exactly one animation"},
        {"skeleton", skeleton_parameters::kTable, {}, "skeleton needs exactly one mesh"},
        {"segment", app::segment_verb_parameters::kTable, {}, "segment needs exactly one animation"},
    };
}

QString flag(const ParameterSpec& spec)
{
    return QStringLiteral("--") + QString::fromUtf8(spec.flag.data(), qsizetype(spec.flag.size()));
}

QString number(double value)
{
    return QString::number(value, 'g', 17);
}

bool numeric(const ParameterSpec& spec)
{
    return spec.kind == ParameterKind::Integer || spec.kind == ParameterKind::Real;
}

std::vector<const ChoiceValue*> commandLineChoices(const ParameterSpec& spec)
{
    std::vector<const ChoiceValue*> choices;
    for (const ChoiceValue& choice : spec.choices)
        if (choice.commandLine)
            choices.push_back(&choice);
    return choices;
}

/// The value of `spec` in accepted run `i`: min and max alternately, every choice in turn.
QString acceptedValue(const ParameterSpec& spec, int i)
{
    if (numeric(spec))
        return number(i % 2 == 0 ? spec.min : spec.max);
    if (spec.kind == ParameterKind::Boolean)
        return i % 2 == 0 ? QStringLiteral("on") : QStringLiteral("off");
    const std::vector<const ChoiceValue*> choices = commandLineChoices(spec);
    const ChoiceValue& choice = *choices[std::size_t(i) % choices.size()];
    return QString::fromUtf8(choice.name.data(), qsizetype(choice.name.size()));
}

/// Values one step outside the row: below and above the range (and a fraction for an
/// integer), an unknown name, a word that is no boolean; none for a switch (it takes no
/// value: a word after it is a source).
QStringList refusedValues(const ParameterSpec& spec)
{
    if (spec.switchFlag)
        return {};
    if (spec.kind == ParameterKind::Choice)
        return {QStringLiteral("no-such-value")};
    if (spec.kind == ParameterKind::Boolean)
        return {QStringLiteral("maybe")};
    if (spec.kind == ParameterKind::Integer)
        return {number(spec.min - 1), number(spec.max + 1), number(spec.min + 0.5)};
    const double margin = std::max(1e-3, 1e-2 * (spec.max - spec.min));
    return {number(spec.min - margin), number(spec.max + margin), QStringLiteral("nan")};
}

/// The run stopped at the verb's check after its table: every value was accepted.
bool stoppedAfterTable(const Run& run, const Verb& verb)
{
    return run.exitCode == 2 && run.err.contains(verb.stopMessage) && run.err.trimmed().count('\n') == 0;
}

} // namespace

class TestParameterTables : public QObject {
    Q_OBJECT
private slots:
    void acceptsEveryValueOfEveryRow();
    void refusesValuesOutsideEveryRow();
    void helpListsEveryRowWithItsRange();
    void everyPanelParameterIsOnTheCommandLine();
};

void TestParameterTables::acceptsEveryValueOfEveryRow()
{
    for (const Verb& verb : verbs()) {
        int runs = 2;
        for (const ParameterSpec* spec : verb.table)
            if (spec->kind == ParameterKind::Choice && !spec->flag.empty())
                runs = std::max(runs, int(commandLineChoices(*spec).size()));
        for (int i = 0; i < runs; ++i) {
            QStringList arguments{QString::fromLatin1(verb.name)};
            for (const ParameterSpec* spec : verb.table) {
                if (spec->flag.empty())
                    continue;
                arguments << flag(*spec);
                if (!spec->switchFlag)
                    arguments << acceptedValue(*spec, i);
            }
            const Run run = runTrimlab(arguments + verb.stop);
            QVERIFY2(stoppedAfterTable(run, verb), qPrintable(arguments.join(' ') + "\n" + run.err));
        }
    }
}

void TestParameterTables::refusesValuesOutsideEveryRow()
{
    static const QRegularExpression range(QStringLiteral(R"(from (\S+) to (\S+), got ')"));
    for (const Verb& verb : verbs()) {
        for (const ParameterSpec* spec : verb.table) {
            if (spec->flag.empty())
                continue;
            for (const QString& value : refusedValues(*spec)) {
                const QStringList arguments{QString::fromLatin1(verb.name), flag(*spec), value};
                const Run run = runTrimlab(arguments + verb.stop);
                const QString context = arguments.join(' ') + "\n" + run.err;
                QCOMPARE(run.exitCode, 2);
                QVERIFY2(run.err.startsWith("trimlab: error: ") && run.err.trimmed().count('\n') == 0,
                         qPrintable(context));
                QVERIFY2(run.err.contains(flag(*spec) + ' ') && run.err.contains(value), qPrintable(context));
                if (!numeric(*spec))
                    continue;
                // The range printed is the row's, to the last digit.
                const QRegularExpressionMatch m = range.match(run.err);
                QVERIFY2(m.hasMatch(), qPrintable(context));
                QCOMPARE(m.captured(1).toDouble(), spec->min);
                QCOMPARE(m.captured(2).toDouble(), spec->max);
            }
        }
    }
}

void TestParameterTables::helpListsEveryRowWithItsRange()
{
    for (const Verb& verb : verbs()) {
        const Run run = runTrimlab({QString::fromLatin1(verb.name), QStringLiteral("--help")});
        QCOMPARE(run.exitCode, 0);
        // QCommandLineParser wraps the help into columns: compare it with the words joined.
        const QString help = run.out.simplified();
        for (const ParameterSpec* spec : verb.table) {
            if (spec->flag.empty())
                continue;
            // QCommandLineParser lists a one-letter option as -k (--k works too).
            const QString shown = spec->flag.size() == 1 ? flag(*spec).mid(1) : flag(*spec);
            if (spec->switchFlag) {
                QVERIFY2(help.contains(shown + ' ') && !help.contains(shown + " <"), qPrintable(flag(*spec)));
                QVERIFY2(help.contains(QStringLiteral("(a switch; off unless given)")), qPrintable(flag(*spec)));
                continue;
            }
            QVERIFY2(help.contains(shown + " <"), qPrintable(flag(*spec)));
            const QString range = QString::fromStdString(parameterRangeText(*spec)).simplified();
            QVERIFY2(help.contains(range), qPrintable(flag(*spec) + ": " + range));
        }
    }
}

// The rows the command line lacks, each for a reason: the panel's posing and colouring
// are views of a result, and --corrections sets both corrections in one list.
void TestParameterTables::everyPanelParameterIsOnTheCommandLine()
{
    const std::vector<const ParameterSpec*> panelOnly = {
        &skeleton_parameters::kPoseSkinning,
        &segmentation_parameters::kColorBySegment,
        &skinning_parameters::kWeightCorrections,
        &skinning_parameters::kVertexCorrections,
    };
    std::vector<const ParameterSpec*> rows(render::method_parameters::kTable.begin(),
                                           render::method_parameters::kTable.end());
    rows.insert(rows.end(), inspect_parameters::kTable.begin(), inspect_parameters::kTable.end());
    rows.insert(rows.end(), skeleton_parameters::kTable.begin(), skeleton_parameters::kTable.end());
    rows.insert(rows.end(), skinning_parameters::kTable.begin(), skinning_parameters::kTable.end());
    rows.insert(rows.end(), segmentation_parameters::kTable.begin(), segmentation_parameters::kTable.end());
    for (const ParameterSpec* spec : rows) {
        const bool listed = std::find(panelOnly.begin(), panelOnly.end(), spec) != panelOnly.end();
        QVERIFY2(spec->flag.empty() == listed, spec->id.data());
    }
}

QTEST_GUILESS_MAIN(TestParameterTables)
#include "tst_parameter_tables.moc"
