#include "ui/animation/pose_history_bar.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>

namespace trimlab::ui {

namespace {

constexpr int kStaticRule = -1; // the rule combo's item data for "Static rule"

QString text(std::string_view name)
{
    return QString::fromUtf8(name.data(), qsizetype(name.size()));
}

} // namespace

PoseHistoryBar::PoseHistoryBar(QWidget* parent) : QWidget(parent)
{
    m_rule = new QComboBox;
    m_rule->setObjectName(QStringLiteral("poseRuleCombo"));
    m_rule->addItem(tr("Static rule (each pose alone)"), kStaticRule);
    for (DynamicRule rule :
         {DynamicRule::Confluent, DynamicRule::HomogeneousConfluent, DynamicRule::ConstructiveAdditive,
          DynamicRule::ConstructiveSubtractive, DynamicRule::ConstructiveIntersection})
        m_rule->addItem(text(dynamicRuleDisplayName(rule)), int(rule));
    m_rule->setToolTip(tr("How the poses are classified. The static rule (Render panel) classifies each pose by "
                          "itself. A dynamic rule treats the animation as a deformation history: a part of the "
                          "surface that passes through another keeps the classification it had before (thesis "
                          "8.1), so what was inside stays inside while the animation plays."));
    m_reference = new QComboBox;
    m_reference->setObjectName(QStringLiteral("poseReferenceCombo"));
    m_reference->addItem(tr("against the previous pose"), int(PoseReference::Previous));
    m_reference->addItem(tr("against the rest pose"), int(PoseReference::Rest));
    m_reference->setToolTip(tr("The reference of each pose. Previous pose: every pose is a set of its own and the "
                               "classification is carried from pose to pose (playing forward costs one pass more per "
                               "pose). Rest pose: every pose is compared with the rest pose directly."));
    m_status = new QLabel;
    m_status->setObjectName(QStringLiteral("poseHistoryStatus"));
    m_status->setToolTip(tr("Sets in the history of the pose shown, and how many were characterized for the last "
                            "frame (0: all cached)"));
    connect(m_rule, &QComboBox::currentIndexChanged, this, [this] {
        updateEnabled();
        emit choicesChanged();
    });
    connect(m_reference, &QComboBox::currentIndexChanged, this, &PoseHistoryBar::choicesChanged);

    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(new QLabel(tr("Classify poses by")));
    layout->addWidget(m_rule);
    layout->addWidget(m_reference);
    layout->addWidget(m_status, 1);
    updateEnabled();
}

void PoseHistoryBar::setChoices(const PoseHistoryChoices& choices)
{
    const QSignalBlocker ruleBlocker(m_rule);
    const QSignalBlocker referenceBlocker(m_reference);
    m_rule->setCurrentIndex(std::max(0, m_rule->findData(choices.rule ? int(*choices.rule) : kStaticRule)));
    m_reference->setCurrentIndex(std::max(0, m_reference->findData(int(choices.reference))));
    updateEnabled();
}

PoseHistoryChoices PoseHistoryBar::choices() const
{
    PoseHistoryChoices choices;
    const int rule = m_rule->currentData().toInt();
    if (rule != kStaticRule)
        choices.rule = DynamicRule(rule);
    choices.reference = PoseReference(m_reference->currentData().toInt());
    return choices;
}

void PoseHistoryBar::setStatus(const QString& status)
{
    m_status->setText(status);
}

void PoseHistoryBar::updateEnabled()
{
    m_reference->setEnabled(m_rule->currentData().toInt() != kStaticRule);
    if (!m_reference->isEnabled())
        m_status->clear();
}

} // namespace trimlab::ui
