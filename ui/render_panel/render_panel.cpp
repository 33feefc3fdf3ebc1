#include "ui/render_panel/render_panel.h"

#include "ui/common/form_controls.h"
#include "ui/common/rule_labels.h"
#include "ui/render_panel/clip_set_editor.h"
#include "ui/render_panel/inspect_group.h"
#include "ui/render_panel/method_group.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>

namespace trimlab::ui {

namespace {

// The item data of the threshold kinds: the rule name without K (the spin box holds K).
const QString kAtLeastPrefix = QStringLiteral("w>=");
const QString kAbsAtLeastPrefix = QStringLiteral("|w|>=");

bool isThresholdItem(const QString& key)
{
    return key == kAtLeastPrefix || key == kAbsAtLeastPrefix;
}

} // namespace

RenderPanel::RenderPanel(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("renderPanel"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(createTrimGroup());
    m_clip = new ClipSetEditor(this);
    connect(m_clip, &ClipSetEditor::clipSetChanged, this, &RenderPanel::renderChoicesChanged);
    connect(m_clip, &ClipSetEditor::viewDirectionRequested, this, &RenderPanel::viewDirectionRequested);
    layout->addWidget(m_clip);
    m_inspect = new InspectGroup(this);
    connect(m_inspect, &InspectGroup::changed, this, &RenderPanel::renderChoicesChanged);
    layout->addWidget(m_inspect);
    m_methodGroup = new MethodGroup(this);
    connect(m_methodGroup, &MethodGroup::changed, this, &RenderPanel::renderChoicesChanged);
    layout->addWidget(m_methodGroup);
    layout->addStretch();
    setRenderChoices(RenderChoices{});
}

QWidget* RenderPanel::createTrimGroup()
{
    auto* group = new QGroupBox(tr("Trim"), this);
    auto* form = new QFormLayout(group);
    m_trim = new QCheckBox(tr("Trim by winding number"), group);
    m_trim->setObjectName(QStringLiteral("trimCheckBox"));
    m_trim->setToolTip(tr("Show the self-trimmed surface: the first point along each ray whose two sides classify "
                          "differently under the rule. Off: ordinary rendering."));
    form->addRow(m_trim);
    m_rule = new QComboBox(group);
    m_rule->setObjectName(QStringLiteral("ruleComboBox"));
    for (StaticRule rule : {StaticRule::Parity, StaticRule::PositiveIndex, StaticRule::AlternatingBorder,
                            StaticRule::Nonzero, StaticRule::Negative}) {
        m_rule->addItem(ruleLabel(rule), ruleKey(rule));
        m_rule->setItemData(m_rule->count() - 1, ruleToolTip(rule), Qt::ToolTipRole);
    }
    m_rule->addItem(tr("w ≥ K"), kAtLeastPrefix);
    m_rule->setItemData(m_rule->count() - 1, tr("Interior where K or more layers of the surface overlap"),
                        Qt::ToolTipRole);
    m_rule->addItem(tr("|w| ≥ K"), kAbsAtLeastPrefix);
    m_rule->setItemData(m_rule->count() - 1, tr("Interior where K or more layers overlap, counting either orientation"),
                        Qt::ToolTipRole);
    form->addRow(tr("Rule"), m_rule);
    m_threshold = new QSpinBox(group);
    m_threshold->setObjectName(QStringLiteral("ruleThresholdSpinBox"));
    m_threshold->setRange(2, StaticRule::kMaxThreshold);
    m_threshold->setToolTip(tr("K of the rules w ≥ K and |w| ≥ K: the number of overlapping layers that counts as "
                               "interior"));
    form->addRow(tr("Layers K"), m_threshold);
    m_classification = new QComboBox(group);
    m_classification->setObjectName(QStringLiteral("classificationComboBox"));
    m_classification->addItem(tr("Static rule"), false);
    m_classification->addItem(tr("Dynamic rules (per set)"), true);
    m_classification->setToolTip(tr("For a deformation history: classify every frame by the static rule alone, or "
                                    "by the dynamic rules of its sets (thesis 8.1.1), the static rule classifying "
                                    "the base mesh. Needs a buffer method (not peeling or two-pass)."));
    form->addRow(tr("Classification"), m_classification);
    m_trimUnavailable = noticeLabel(group, "trimUnavailableLabel", NoticeKind::Warning);
    form->addRow(m_trimUnavailable);
    connect(m_trim, &QCheckBox::toggled, this, &RenderPanel::renderChoicesChanged);
    connect(m_rule, &QComboBox::currentIndexChanged, this, [this] {
        refreshThresholdEnabled();
        emit renderChoicesChanged();
    });
    connect(m_threshold, &QSpinBox::valueChanged, this, &RenderPanel::renderChoicesChanged);
    connect(m_classification, &QComboBox::currentIndexChanged, this, &RenderPanel::renderChoicesChanged);
    return group;
}

void RenderPanel::setRenderChoices(const RenderChoices& choices)
{
    const QSignalBlocker trimBlocker(m_trim);
    const QSignalBlocker ruleBlocker(m_rule);
    const QSignalBlocker classificationBlocker(m_classification);
    const QSignalBlocker thresholdBlocker(m_threshold);
    m_classification->setCurrentIndex(choices.dynamicRules ? 1 : 0);
    m_trim->setChecked(choices.trim.trimEnabled);
    const StaticRule rule = choices.trim.rule;
    if (rule.isThreshold()) {
        m_rule->setCurrentIndex(
            m_rule->findData(rule.kind() == StaticRule::Kind::AtLeast ? kAtLeastPrefix : kAbsAtLeastPrefix));
        m_threshold->setValue(rule.threshold());
    } else {
        m_rule->setCurrentIndex(m_rule->findData(ruleKey(rule)));
    }
    refreshThresholdEnabled();
    m_clip->setClipSet(choices.trim.clipSet());
    m_inspect->setChoices(choices.trim.cap, choices.capSpacingFraction, choices.trim.highlight);
    m_inspect->setTransparency(choices.trim.transparency);
    m_methodGroup->setChoices(choices.method, choices.k, choices.sharedCounters);
    m_methodGroup->setMemoryBudgetMegabytes(choices.memoryBudgetMegabytes);
}

RenderChoices RenderPanel::renderChoices() const
{
    RenderChoices choices;
    choices.trim.trimEnabled = m_trim->isChecked();
    choices.trim.rule = chosenRule();
    choices.trim.setClipSet(m_clip->clipSet());
    choices.capSpacingFraction = m_inspect->spacingFraction();
    choices.trim.cap = m_inspect->cap();
    // World units on the scene shown (the command line's rule: a fraction of its radius).
    const double radius = m_bounds.valid() ? m_bounds.radius() : 1.0;
    choices.trim.cap.spacing = choices.capSpacingFraction * (radius > 0.0 ? radius : 1.0);
    choices.trim.highlight = m_inspect->highlight();
    choices.trim.transparency = m_inspect->transparency();
    choices.method = m_methodGroup->method();
    choices.k = m_methodGroup->k();
    choices.sharedCounters = m_methodGroup->sharedCounters();
    choices.memoryBudgetMegabytes = m_methodGroup->memoryBudgetMegabytes();
    choices.dynamicRules = m_classification->currentData().toBool();
    return choices;
}

StaticRule RenderPanel::chosenRule() const
{
    QString key = m_rule->currentData().toString();
    if (isThresholdItem(key))
        key += QString::number(m_threshold->value());
    return parseStaticRule(key.toStdString()).value_or(StaticRule::AlternatingBorder);
}

void RenderPanel::refreshThresholdEnabled()
{
    m_threshold->setEnabled(m_rule->isEnabled() && isThresholdItem(m_rule->currentData().toString()));
}

void RenderPanel::setSceneInfo(const Bounds& bounds, bool trimmable, const QString& reason)
{
    m_trimmable = trimmable;
    m_bounds = bounds;
    m_clip->setSceneBounds(bounds);
    m_trim->setEnabled(trimmable);
    m_rule->setEnabled(trimmable);
    refreshThresholdEnabled();
    m_classification->setEnabled(trimmable);
    m_trimUnavailable->setText(trimmable ? QString() : tr("Trim modes unavailable: %1").arg(reason));
    m_trimUnavailable->setVisible(!trimmable);
}

void RenderPanel::setClipBounds(const Bounds& bounds)
{
    m_bounds = bounds;
    m_clip->setSceneBounds(bounds);
}

void RenderPanel::setMemoryEstimate(const MemoryEstimate& estimate)
{
    m_methodGroup->setMemoryEstimate(estimate);
}

void RenderPanel::setClipNormal(const glm::dvec3& viewDirection)
{
    m_clip->setNormalThroughCenter(viewDirection);
}

} // namespace trimlab::ui
