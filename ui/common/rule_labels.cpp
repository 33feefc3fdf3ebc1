#include "ui/common/rule_labels.h"

#include "core/trim/csg_expression.h"

#include <QComboBox>
#include <QCoreApplication>

namespace trimlab::ui {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("RuleLabels", text);
}

} // namespace

QString ruleLabel(StaticRule rule)
{
    switch (rule.kind()) {
    case StaticRule::Kind::Parity:
        return tr("Parity");
    case StaticRule::Kind::PositiveIndex:
        return tr("Positive index");
    case StaticRule::Kind::AlternatingBorder:
        return tr("Alternating border");
    case StaticRule::Kind::Nonzero:
        return tr("Nonzero");
    case StaticRule::Kind::Negative:
        return tr("Negative");
    case StaticRule::Kind::AtLeast:
        return tr("w ≥ %1").arg(rule.threshold());
    case StaticRule::Kind::AbsAtLeast:
        return tr("|w| ≥ %1").arg(rule.threshold());
    }
    return QString();
}

QString ruleToolTip(StaticRule rule)
{
    switch (rule.kind()) {
    case StaticRule::Kind::Parity:
        return tr("Interior where the winding index is odd");
    case StaticRule::Kind::PositiveIndex:
        return tr("Interior where the winding index is at least 1");
    case StaticRule::Kind::AlternatingBorder:
        return tr("Interior where the winding index mod 4 is 1 or 2");
    case StaticRule::Kind::Nonzero:
        return tr("Interior where the winding index is not 0 (the cells an exact self-union keeps, as in Blender, "
                  "SVG and PostScript)");
    case StaticRule::Kind::Negative:
        return tr("Interior where the winding index is below 0: pockets the surface wraps inside out");
    case StaticRule::Kind::AtLeast:
        return tr("Interior where the winding index is at least %1: where %1 or more layers overlap")
            .arg(rule.threshold());
    case StaticRule::Kind::AbsAtLeast:
        return tr("Interior where the winding index is at least %1 in magnitude, either orientation")
            .arg(rule.threshold());
    }
    return QString();
}

QString classificationLabel(const TrimSettings& settings)
{
    if (settings.csg.enabled())
        return tr("the CSG %1").arg(QString::fromStdString(formatCsgExpression(settings.csg.expression)));
    return tr("the %1 rule").arg(ruleLabel(settings.rule).toLower());
}

QString ruleKey(StaticRule rule)
{
    return QString::fromStdString(ruleName(rule));
}

void addRuleItems(QComboBox* combo)
{
    for (StaticRule rule : {StaticRule::Parity, StaticRule::PositiveIndex, StaticRule::AlternatingBorder,
                            StaticRule::Nonzero, StaticRule::Negative, StaticRule::atLeast(2), StaticRule::atLeast(3),
                            StaticRule::absAtLeast(2), StaticRule::absAtLeast(3)}) {
        combo->addItem(ruleLabel(rule), ruleKey(rule));
        combo->setItemData(combo->count() - 1, ruleToolTip(rule), Qt::ToolTipRole);
    }
}

void selectRule(QComboBox* combo, StaticRule rule)
{
    int index = combo->findData(ruleKey(rule));
    if (index < 0) {
        combo->addItem(ruleLabel(rule), ruleKey(rule));
        index = combo->count() - 1;
        combo->setItemData(index, ruleToolTip(rule), Qt::ToolTipRole);
    }
    combo->setCurrentIndex(index);
}

std::optional<StaticRule> currentRule(const QComboBox* combo)
{
    return parseStaticRule(combo->currentData().toString().toStdString());
}

} // namespace trimlab::ui
