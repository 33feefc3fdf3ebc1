#include "ui/render_panel/inspect_group.h"

#include "ui/common/form_controls.h"
#include "ui/common/parameter_form.h"
#include "ui/render_panel/render_choices.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QSignalBlocker>

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>

namespace trimlab::ui {

namespace {

struct PatternEntry {
    CapPattern pattern;
    const char* label;
};

/// Combo box order; the item data is the stable capPatternName().
constexpr std::array<PatternEntry, 3> kPatterns = {{
    {CapPattern::Hatched, QT_TRANSLATE_NOOP("InspectGroup", "Hatched")},
    {CapPattern::Striped, QT_TRANSLATE_NOOP("InspectGroup", "Striped")},
    {CapPattern::Solid, QT_TRANSLATE_NOOP("InspectGroup", "Solid")},
}};

QString patternKey(CapPattern pattern)
{
    const std::string_view name = capPatternName(pattern);
    return QString::fromLatin1(name.data(), qsizetype(name.size()));
}

// The cap spacing is a fraction of the radius, shown as a percentage.
constexpr double kPercent = 100.0;

// The X-ray combo box's item data: "off" or trimDisplayName().
const QString kXrayOff = QStringLiteral("off");

QString displayKey(TrimDisplay display)
{
    const std::string_view name = trimDisplayName(display);
    return QString::fromLatin1(name.data(), qsizetype(name.size()));
}

} // namespace

InspectGroup::InspectGroup(QWidget* parent) : QGroupBox(tr("Capping and highlighting"), parent)
{
    setObjectName(QStringLiteral("inspectGroup"));
    auto* form = new QFormLayout(this);
    m_unavailable = noticeLabel(this, "inspectUnavailableLabel", NoticeKind::Warning);
    form->addRow(m_unavailable);
    m_cap = new QCheckBox(tr("Cap the cut"), this);
    m_cap->setObjectName(QStringLiteral("capCheckBox"));
    m_cap->setToolTip(tr("Where a clipping plane cuts into the solid (under the rule, or the CSG result), show the "
                         "cut face with a pattern instead of the interior behind it. Needs trimming and an enabled "
                         "clipping plane."));
    form->addRow(m_cap);
    form->addRow(createCapRows());
    m_collisions = new QCheckBox(tr("Highlight collisions"), this);
    m_collisions->setObjectName(QStringLiteral("highlightCollisionsCheckBox"));
    m_collisions->setToolTip(tr("Tint shown surface points red that lie inside another object, or where an object "
                                "overlaps itself. Needs a buffer method (not peeling or two-pass)."));
    m_coplanar = new QCheckBox(tr("Highlight coplanar fragments"), this);
    m_coplanar->setObjectName(QStringLiteral("highlightCoplanarCheckBox"));
    m_coplanar->setToolTip(tr("Color shown surface points that share their depth with other surfaces by the size of "
                              "the group: 2 red, 3 blue, 4 green, 5 cyan, 6 aquamarine, 7 fuchsia, 8 yellow, 9+ "
                              "brown. Needs a buffer method."));
    form->addRow(m_collisions);
    form->addRow(m_coplanar);
    form->addRow(createXrayRows());
    connect(m_cap, &QCheckBox::toggled, this, [this] {
        updateEnabled();
        emit changed();
    });
    connect(m_pattern, &QComboBox::currentIndexChanged, this, &InspectGroup::changed);
    connect(m_spacing, &QDoubleSpinBox::valueChanged, this, &InspectGroup::changed);
    connect(m_collisions, &QCheckBox::toggled, this, &InspectGroup::changed);
    connect(m_coplanar, &QCheckBox::toggled, this, &InspectGroup::changed);
    connect(m_xrayMode, &QComboBox::currentIndexChanged, this, [this] {
        updateEnabled();
        emit changed();
    });
    for (QDoubleSpinBox* spin : {m_layerAlpha, m_ghostAlpha, m_density, m_fresnel})
        connect(spin, &QDoubleSpinBox::valueChanged, this, &InspectGroup::changed);
    setChoices(CapSettings{}, inspect_parameters::kCapSpacing.defaultValue, HighlightSettings{});
    setTransparency(TransparencySettings{});
}

QWidget* InspectGroup::createXrayRows()
{
    auto* rows = new QWidget(this);
    auto* form = new QFormLayout(rows);
    form->setContentsMargins(0, 0, 0, 0);
    m_xrayMode = new QComboBox(rows);
    m_xrayMode->setObjectName(QStringLiteral("xrayModeComboBox"));
    m_xrayMode->addItem(tr("Off"), kXrayOff);
    m_xrayMode->addItem(tr("Opaque trim + ghosts"), displayKey(TrimDisplay::Opaque));
    m_xrayMode->addItem(tr("Translucent"), displayKey(TrimDisplay::Translucent));
    m_xrayMode->setToolTip(tr("Transparency over every fragment of the kept span, in depth order. Opaque trim + "
                              "ghosts: the trimmed solid as usual, with the surface the trim removed in front of it "
                              "as translucent ghosts. Translucent: every boundary of the trimmed solid (caps too) as "
                              "a translucent layer. Needs a buffer method (not peeling or two-pass)."));
    form->addRow(tr("X-ray"), m_xrayMode);
    m_layerAlpha = parameterDoubleSpinBox(inspect_parameters::kLayerAlpha, "xrayLayerAlphaSpin", rows);
    m_ghostAlpha = parameterDoubleSpinBox(inspect_parameters::kGhostAlpha, "xrayGhostAlphaSpin", rows);
    m_density = parameterDoubleSpinBox(inspect_parameters::kDensity, "xrayDensitySpin", rows);
    m_fresnel = parameterDoubleSpinBox(inspect_parameters::kFresnel, "xrayFresnelSpin", rows);
    form->addRow(tr("Layer opacity"), m_layerAlpha);
    form->addRow(tr("Ghost opacity"), m_ghostAlpha);
    form->addRow(tr("Density"), m_density);
    form->addRow(tr("Fresnel"), m_fresnel);
    return rows;
}

void InspectGroup::setTransparency(const TransparencySettings& transparency)
{
    const QSignalBlocker modeBlocker(m_xrayMode);
    const QSignalBlocker layerBlocker(m_layerAlpha);
    const QSignalBlocker ghostBlocker(m_ghostAlpha);
    const QSignalBlocker densityBlocker(m_density);
    const QSignalBlocker fresnelBlocker(m_fresnel);
    const QString key = transparency.enabled ? displayKey(transparency.display) : kXrayOff;
    m_xrayMode->setCurrentIndex(std::max(0, m_xrayMode->findData(key)));
    auto finite = [](double x) { return std::isfinite(x) ? x : 0.0; };
    m_layerAlpha->setValue(finite(transparency.layerAlpha)); // the spin boxes clamp to their ranges
    m_ghostAlpha->setValue(finite(transparency.ghostAlpha));
    m_density->setValue(finite(transparency.density));
    m_fresnel->setValue(finite(transparency.fresnelExponent));
    updateEnabled();
}

TransparencySettings InspectGroup::transparency() const
{
    TransparencySettings xray;
    const std::optional<TrimDisplay> display = parseTrimDisplay(m_xrayMode->currentData().toString().toStdString());
    xray.enabled = display.has_value();
    xray.display = display.value_or(TrimDisplay::Translucent);
    xray.layerAlpha = m_layerAlpha->value();
    xray.ghostAlpha = m_ghostAlpha->value();
    xray.density = m_density->value();
    xray.fresnelExponent = m_fresnel->value();
    return xray;
}

QWidget* InspectGroup::createCapRows()
{
    auto* rows = new QWidget(this);
    auto* form = new QFormLayout(rows);
    form->setContentsMargins(16, 0, 0, 0);
    m_pattern = new QComboBox(rows);
    m_pattern->setObjectName(QStringLiteral("capPatternComboBox"));
    for (const PatternEntry& entry : kPatterns)
        m_pattern->addItem(tr(entry.label), patternKey(entry.pattern));
    m_pattern->setToolTip(tr("Lines drawn on the cap, fixed in the world (they do not swim with the camera)"));
    form->addRow(tr("Pattern"), m_pattern);
    m_spacing = new QDoubleSpinBox(rows);
    m_spacing->setObjectName(QStringLiteral("capSpacingSpin"));
    applyParameter(m_spacing, inspect_parameters::kCapSpacing, kPercent);
    m_spacing->setSuffix(tr(" % of radius"));
    form->addRow(tr("Spacing"), m_spacing);
    return rows;
}

void InspectGroup::setChoices(const CapSettings& cap, double spacingFraction, const HighlightSettings& highlight)
{
    const QSignalBlocker capBlocker(m_cap);
    const QSignalBlocker patternBlocker(m_pattern);
    const QSignalBlocker spacingBlocker(m_spacing);
    const QSignalBlocker collisionsBlocker(m_collisions);
    const QSignalBlocker coplanarBlocker(m_coplanar);
    m_cap->setChecked(cap.enabled);
    m_pattern->setCurrentIndex(std::max(0, m_pattern->findData(patternKey(cap.pattern))));
    const double fraction =
        std::isfinite(spacingFraction) ? spacingFraction : inspect_parameters::kCapSpacing.defaultValue;
    m_spacing->setValue(kPercent * fraction); // the spin box clamps to its range
    m_collisions->setChecked(highlight.collisions);
    m_coplanar->setChecked(highlight.coplanar);
    updateEnabled();
}

CapSettings InspectGroup::cap() const
{
    CapSettings cap;
    cap.enabled = m_cap->isChecked();
    cap.pattern = parseCapPattern(m_pattern->currentData().toString().toStdString()).value_or(CapPattern::Hatched);
    return cap;
}

double InspectGroup::spacingFraction() const
{
    return m_spacing->value() / kPercent;
}

HighlightSettings InspectGroup::highlight() const
{
    return {m_collisions->isChecked(), m_coplanar->isChecked()};
}

void InspectGroup::setUnavailableReason(const QString& reason)
{
    m_unavailable->setText(reason);
    m_unavailable->setVisible(!reason.isEmpty());
    updateEnabled();
}

void InspectGroup::updateEnabled()
{
    const bool available = m_unavailable->text().isEmpty();
    for (QWidget* control : std::initializer_list<QWidget*>{m_cap, m_collisions, m_coplanar, m_xrayMode})
        control->setEnabled(available);
    m_pattern->setEnabled(available && m_cap->isChecked());
    m_spacing->setEnabled(available && m_cap->isChecked());
    const bool xray = available && m_xrayMode->currentData().toString() != kXrayOff;
    m_layerAlpha->setEnabled(xray && transparency().display == TrimDisplay::Translucent);
    for (QDoubleSpinBox* spin : {m_ghostAlpha, m_density, m_fresnel})
        spin->setEnabled(xray);
}

} // namespace trimlab::ui
