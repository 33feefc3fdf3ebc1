// The panels and the settings against the parameter tables, for render (the Render
// panel's method and inspection rows, which bench shares), skin, skeleton and segment:
// every control of a row in the real panel has the row's range, default, choices and
// help, and every row the panel persists is read back from a settings file as written
// when it lies in the row's range and as the row's default when it does not (one step
// beyond either end, a word, an unknown name). The command line is walked against the
// same tables by tests/app/tst_parameter_tables.cpp.
#include "named_child.h"

#include "ui/animation/animation_settings_store.h"
#include "ui/animation/segmentation_panel.h"
#include "ui/render_panel/render_panel.h"
#include "ui/render_panel/render_settings_store.h"
#include "ui/skeleton/skeleton_panel.h"
#include "ui/skeleton/skeleton_settings_store.h"
#include "ui/skinning/skinning_panel.h"

#include "core/animation/segmentation_parameters.h"
#include "core/skeleton/skeleton_parameters.h"
#include "core/skinning/skinning_parameters.h"
#include "core/trim/inspect_parameters.h"
#include "render/mfr/method_parameter_table.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSettings>
#include <QSlider>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <span>
#include <vector>

using namespace trimlab;
using namespace trimlab::ui;
using trimlab::test::child;

namespace {

QString text(std::string_view view)
{
    return QString::fromUtf8(view.data(), qsizetype(view.size()));
}

/// A row's control in its panel, found by object name; `scale` where the panel shows a
/// multiple of the value (a fraction as percent, h in slider steps).
struct Control {
    const ParameterSpec* spec;
    const char* objectName;
    double scale = 1.0;
};

/// A panel, the controls of its operation's rows, and the rows (of `table`) it must show.
struct Panel {
    const char* operation;
    std::function<QWidget*()> make;
    std::vector<Control> controls;
    std::vector<const ParameterSpec*> rows;
};

template <std::size_t N>
std::vector<const ParameterSpec*> rowsOf(const std::array<const ParameterSpec*, N>& table)
{
    return {table.begin(), table.end()};
}

std::vector<Panel> panels()
{
    using namespace skeleton_parameters;
    namespace method = render::method_parameters;
    namespace inspect = inspect_parameters;
    namespace skin = skinning_parameters;
    namespace segment = segmentation_parameters;
    std::vector<const ParameterSpec*> render = rowsOf(method::kTable);
    for (const ParameterSpec* spec : inspect::kTable)
        render.push_back(spec);
    std::vector<const ParameterSpec*> skeleton;
    for (const ParameterSpec* spec : kTable)
        if (spec != &kLoopSubdivisions) // the command line's: the panel extracts from the mesh shown
            skeleton.push_back(spec);
    return {
        {"render",
         [] { return new RenderPanel; },
         {{&method::kK, "kSpinBox"},
          {&method::kSharedCounters, "sharedCountersSpinBox"},
          {&method::kMemoryBudget, "memoryBudgetSpinBox"},
          {&inspect::kLayerAlpha, "xrayLayerAlphaSpin"},
          {&inspect::kGhostAlpha, "xrayGhostAlphaSpin"},
          {&inspect::kDensity, "xrayDensitySpin"},
          {&inspect::kFresnel, "xrayFresnelSpin"},
          {&inspect::kCapSpacing, "capSpacingSpin", 100.0}},
         render},
        {"skeleton",
         [] { return new SkeletonPanel; },
         {{&kInitialContractionWeight, "skeletonInitialWeightSpinBox"},
          {&kContractionGrowth, "skeletonGrowthSpinBox"},
          {&kMaxContractionWeight, "skeletonMaxContractionSpinBox"},
          {&kMaxAttractionWeight, "skeletonMaxAttractionSpinBox"},
          {&kMaxIterations, "skeletonIterationsSpinBox"},
          {&kOrdering, "skeletonOrderingComboBox"},
          {&kSolver, "skeletonSolverComboBox"},
          {&kPreCollapseFraction, "skeletonDeltaSpinBox"},
          {&kShapeWeight, "skeletonShapeWeightSpinBox"},
          {&kSamplingWeight, "skeletonSamplingWeightSpinBox"},
          {&kRefine, "skeletonRefineCheckBox"},
          {&kTargetNodes, "skeletonNodesSpinBox"},
          {&kRootJoint, "skeletonRootSpinBox"},
          {&kHeatConstant, "skeletonHeatConstantSpinBox"},
          {&kPoseSkinning, "skeletonSkinningComboBox"}},
         skeleton},
        {"skin",
         [] { return new SkinningPanel; },
         {{&skin::kBones, "skinningBoneCountSpinBox"},
          {&skin::kFit, "skinningMethodComboBox"},
          {&skin::kChain, "skinningChainComboBox"},
          {&skin::kInfluences, "skinningInfluencesSpinBox"},
          {&skin::kWeightCorrections, "weightCorrectionsCheckBox"},
          {&skin::kVertexCorrections, "vertexCorrectionsCheckBox"},
          {&skin::kInterpolation, "skinningInterpolationComboBox"}},
         {&skin::kBones, &skin::kFit, &skin::kChain, &skin::kInfluences, &skin::kWeightCorrections,
          &skin::kVertexCorrections, &skin::kInterpolation}},
        {"segment",
         [] { return new SegmentationPanel; },
         {{&segment::kFeature, "featureComboBox"},
          {&segment::kReference, "referenceComboBox"},
          {&segment::kMethod, "clusteringComboBox"},
          {&segment::kClusters, "clustersSpinBox"},
          {&segment::kThreads, "threadsSpinBox"},
          {&segment::kH, "hSlider", double(SegmentationPanel::kHSteps)},
          {&segment::kMode, "modeComboBox"},
          {&segment::kColorBySegment, "colorBySegmentCheckBox"}},
         rowsOf(segment::kTable)},
    };
}

/// Compares `control` with its row (its value with the row's default unless `forced`: the
/// other choices of the panel fix it); the caller names the row when this fails.
void compareControl(QWidget* panel, const Control& control)
{
    const ParameterSpec& spec = *control.spec;
    // The rigid fit, the default, is always rest-to-pose: the chain box shows that (disabled)
    // and keeps the row's default for LBS and DQS.
    if (&spec == &skinning_parameters::kChain)
        QCOMPARE(panel->findChild<QComboBox*>(QLatin1String(control.objectName))->isEnabled(), false);
    const bool forced = &spec == &skinning_parameters::kChain;
    const QString help = text(spec.help);
    if (auto* box = panel->findChild<QSpinBox*>(QLatin1String(control.objectName))) {
        QCOMPARE(box->minimum(), int(spec.min));
        QCOMPARE(box->maximum(), int(spec.max));
        QCOMPARE(box->value(), int(spec.defaultValue));
        QVERIFY(box->toolTip().contains(help));
    } else if (auto* real = panel->findChild<QDoubleSpinBox*>(QLatin1String(control.objectName))) {
        QCOMPARE(real->minimum(), spec.min * control.scale);
        QCOMPARE(real->maximum(), spec.max * control.scale);
        QCOMPARE(real->value(), spec.defaultValue * control.scale);
        QVERIFY(real->toolTip().contains(help));
    } else if (auto* slider = panel->findChild<QSlider*>(QLatin1String(control.objectName))) {
        QCOMPARE(slider->minimum() / control.scale, spec.min);
        QCOMPARE(slider->maximum() / control.scale, spec.max);
        QCOMPARE(slider->value() / control.scale, spec.defaultValue);
        QVERIFY(slider->toolTip().contains(help));
    } else if (auto* combo = panel->findChild<QComboBox*>(QLatin1String(control.objectName))) {
        QCOMPARE(std::size_t(combo->count()), spec.choices.size());
        for (int i = 0; i < combo->count(); ++i) {
            QCOMPARE(combo->itemData(i).toInt(), spec.choices[std::size_t(i)].value);
            QCOMPARE(combo->itemText(i), text(spec.choices[std::size_t(i)].label));
        }
        if (!forced)
            QCOMPARE(combo->currentData().toInt(), int(spec.defaultValue));
        QVERIFY(combo->toolTip().contains(help));
    } else {
        auto* check = child<QCheckBox>(panel, control.objectName);
        QVERIFY(check);
        QCOMPARE(check->isChecked(), spec.defaultValue != 0.0);
        QVERIFY(check->toolTip().contains(help));
    }
}

/// A value the settings file holds, and the value the store must read back for it.
struct Stored {
    QVariant written;
    double expected;
};

std::vector<Stored> storedCases(const ParameterSpec& spec)
{
    const double fallback = spec.defaultValue;
    switch (spec.kind) {
    case ParameterKind::Choice: {
        std::vector<Stored> cases{{QStringLiteral("no-such-choice"), fallback}, {QString(), fallback}};
        for (const ChoiceValue& choice : spec.choices)
            cases.push_back({text(choice.name), double(choice.value)});
        return cases;
    }
    case ParameterKind::Boolean:
        return {{true, 1.0}, {false, 0.0}, {QStringLiteral("maybe"), fallback}};
    case ParameterKind::Integer:
        return {{spec.min, spec.min},     {spec.max, spec.max},       {spec.min - 1, fallback},
                {spec.max + 1, fallback}, {spec.min + 0.5, fallback}, {QStringLiteral("many"), fallback}};
    case ParameterKind::Real:
        break;
    }
    const double margin = std::max(1e-3, 1e-2 * (spec.max - spec.min));
    return {{spec.min, spec.min},
            {spec.max, spec.max},
            {spec.min - margin, fallback},
            {spec.max + margin, fallback},
            {QStringLiteral("nan"), fallback},
            {QStringLiteral("lots"), fallback}};
}

/// What the store wrote for `spec`, as a value of the row.
double storedValue(const QSettings& settings, const ParameterSpec& spec)
{
    const QVariant value = settings.value(text(spec.settingsKey));
    switch (spec.kind) {
    case ParameterKind::Choice: {
        const ChoiceValue* choice = findChoice(spec, value.toString().toStdString());
        return choice ? double(choice->value) : -1e9;
    }
    case ParameterKind::Boolean:
        return value.toBool() ? 1.0 : 0.0;
    case ParameterKind::Integer:
    case ParameterKind::Real:
        break;
    }
    return value.toDouble();
}

/// A store: load the choices from one settings file and save them into another.
struct Store {
    const char* operation;
    std::function<void(const QSettings&, QSettings&)> loadAndSave;
    std::vector<const ParameterSpec*> rows;
};

std::vector<Store> stores()
{
    std::vector<Store> result;
    for (const Panel& panel : panels()) {
        std::vector<const ParameterSpec*> persisted;
        for (const ParameterSpec* spec : panel.rows)
            if (!spec->settingsKey.empty())
                persisted.push_back(spec);
        if (persisted.empty())
            continue;
        const std::string operation = panel.operation;
        std::function<void(const QSettings&, QSettings&)> loadAndSave;
        if (operation == "render")
            loadAndSave = [](const QSettings& in, QSettings& out) { saveRenderChoices(out, loadRenderChoices(in)); };
        else if (operation == "skeleton")
            loadAndSave = [](const QSettings& in, QSettings& out) {
                saveSkeletonChoices(out, loadSkeletonChoices(in));
            };
        else if (operation == "segment")
            loadAndSave = [](const QSettings& in, QSettings& out) {
                saveSegmentationChoices(out, loadSegmentationChoices(in));
            };
        result.push_back({panel.operation, loadAndSave, persisted});
    }
    return result;
}

} // namespace

class TestParameterTables : public QObject {
    Q_OBJECT
private slots:
    void panelsShowEveryRowAsTheTableSays();
    void settingsKeepValuesInRangeAndFallBackOutside();
};

void TestParameterTables::panelsShowEveryRowAsTheTableSays()
{
    for (const Panel& panel : panels()) {
        const std::unique_ptr<QWidget> widget(panel.make());
        for (const ParameterSpec* row : panel.rows) {
            const auto control = std::find_if(panel.controls.begin(), panel.controls.end(),
                                              [row](const Control& c) { return c.spec == row; });
            QVERIFY2(
                control != panel.controls.end(),
                qPrintable(QString("%1: no control for %2").arg(QLatin1String(panel.operation)).arg(text(row->id))));
            compareControl(widget.get(), *control);
            if (QTest::currentTestFailed())
                qWarning("%s: row %s (%s)", panel.operation, row->id.data(), control->objectName);
            QVERIFY(!QTest::currentTestFailed());
        }
    }
}

void TestParameterTables::settingsKeepValuesInRangeAndFallBackOutside()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    int file = 0;
    QVERIFY(!stores().empty());
    for (const Store& store : stores()) {
        for (const ParameterSpec* spec : store.rows) {
            for (const Stored& stored : storedCases(*spec)) {
                const QString in = dir.filePath(QStringLiteral("in%1.ini").arg(++file));
                const QString out = dir.filePath(QStringLiteral("out%1.ini").arg(file));
                {
                    QSettings written(in, QSettings::IniFormat);
                    written.setValue(text(spec->settingsKey), stored.written);
                }
                const QSettings loaded(in, QSettings::IniFormat);
                QSettings saved(out, QSettings::IniFormat);
                store.loadAndSave(loaded, saved);
                const double value = storedValue(saved, *spec);
                QVERIFY2(std::abs(value - stored.expected) <= 1e-12 * std::max(1.0, std::abs(stored.expected)),
                         qPrintable(QString("%1 %2 = '%3': read %4, expected %5")
                                        .arg(QLatin1String(store.operation), text(spec->settingsKey),
                                             stored.written.toString())
                                        .arg(value)
                                        .arg(stored.expected)));
            }
        }
    }
}

QTEST_MAIN(TestParameterTables)
#include "tst_parameter_tables.moc"
