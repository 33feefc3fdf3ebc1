// Small shared pieces of the panels: counts with their noun, point conversions, the mesh
// file filter of the open dialogs, and the rule labels and combo boxes.
#include "ui/common/count_text.h"
#include "ui/common/glm_points.h"
#include "ui/common/mesh_file_filter.h"
#include "ui/common/rule_labels.h"

#include "core/mesh/mesh_io.h"

#include "widget_test_main.h"

#include <QComboBox>
#include <QLocale>
#include <QtTest>

using namespace trimlab;
using namespace trimlab::ui;

class TestCommonParts : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates)); }

    void countsTakeTheirNoun()
    {
        QCOMPARE(countOf(1, "face", "faces"), QString("1 face"));
        QCOMPARE(countOf(0, "face", "faces"), QString("0 faces"));
        QCOMPARE(countOf(12345, "face", "faces"), QString("12,345 faces"));
    }

    void pointsConvertToGlm()
    {
        QCOMPARE(toGlm(QPointF(1.5, -2.0)), glm::dvec2(1.5, -2.0));
        QCOMPARE(toGlm(QSize(640, 480)), glm::ivec2(640, 480));
        const std::vector<std::optional<glm::dvec2>> points = toGlm({QPointF(1, 2), std::nullopt});
        QCOMPARE(points.size(), std::size_t(2));
        QCOMPARE(points[0], std::optional(glm::dvec2(1, 2)));
        QVERIFY(!points[1]);
    }

    // Every extension the loader takes is in the first filter; each format is offered
    // with its gzip variant; the last filter takes any file.
    void meshFilterListsEveryExtension()
    {
        const QString filter = meshFileDialogFilter();
        const QStringList filters = filter.split(";;");
        QVERIFY(filters.size() >= 3);
        QVERIFY(filters.last().contains("(*)"));
        for (const std::string& extension : supportedMeshExtensions())
            QVERIFY2(filters.first().contains("*." + QString::fromStdString(extension)), extension.c_str());
        QVERIFY(filters.contains("OBJ (*.obj *.obj.gz)"));
    }

    void rulesFillAndSelectTheCombo()
    {
        QCOMPARE(ruleLabel(StaticRule::atLeast(3)), QString("w ≥ 3"));
        QCOMPARE(ruleLabel(StaticRule::absAtLeast(2)), QString("|w| ≥ 2"));
        QCOMPARE(ruleLabel(StaticRule::Parity), QString("Parity"));
        QVERIFY(ruleToolTip(StaticRule::atLeast(4)).contains("4 or more layers"));

        QComboBox combo;
        addRuleItems(&combo);
        QCOMPARE(combo.count(), 9);
        for (int i = 0; i < combo.count(); ++i)
            QVERIFY(!combo.itemData(i, Qt::ToolTipRole).toString().isEmpty());
        selectRule(&combo, StaticRule::Nonzero);
        QCOMPARE(currentRule(&combo), std::optional(StaticRule::Nonzero));
        QCOMPARE(combo.currentData().toString(), ruleKey(StaticRule::Nonzero));
        selectRule(&combo, StaticRule::atLeast(7)); // not a preset: appended, then selected
        QCOMPARE(combo.count(), 10);
        QCOMPARE(currentRule(&combo), std::optional(StaticRule::atLeast(7)));
        selectRule(&combo, StaticRule::atLeast(7));
        QCOMPARE(combo.count(), 10);
        combo.addItem("Scene rule");
        combo.setCurrentIndex(combo.count() - 1);
        QVERIFY(!currentRule(&combo));
    }
};

TRIMLAB_WIDGET_TEST_MAIN(TestCommonParts)
#include "tst_common_parts.moc"
