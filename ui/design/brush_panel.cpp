#include "ui/design/brush_panel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace trimlab::ui {

namespace {

QString latin1(std::string_view text)
{
    return QString::fromLatin1(text.data(), qsizetype(text.size()));
}

/// Enough decimals to show a length of about `scale` with three significant digits.
// Enough decimals to show `smallest` with one significant digit (0.005 → 3): the radius
// reads "0.150", not "0.150000" (a newcomer's complaint), and the minimum stays exact.
int decimalsFor(double smallest)
{
    return std::clamp(-int(std::floor(std::log10(smallest))), 1, 8);
}

} // namespace

BrushPanel::BrushPanel(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("brushPanel"));
    createControls();
    setMeshRadius(0.0);
}

void BrushPanel::createControls()
{
    auto* layout = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    layout->addLayout(form);
    m_radius = new QDoubleSpinBox(this);
    m_radius->setObjectName(QStringLiteral("brushRadiusSpinBox"));
    m_radius->setToolTip(tr("Geodesic radius of influence, in the mesh's units: vertices farther along the surface "
                            "from the grabbed point do not move."));
    form->addRow(tr("Radius"), m_radius);
    m_strength = new QDoubleSpinBox(this);
    m_strength->setObjectName(QStringLiteral("brushStrengthSpinBox"));
    m_strength->setRange(-BrushChoices::kMaxStrength, BrushChoices::kMaxStrength);
    m_strength->setSingleStep(0.1);
    m_strength->setToolTip(tr("Scales the drag: 1 makes the grabbed point follow the cursor, negative pushes "
                              "against it."));
    form->addRow(tr("Strength"), m_strength);
    m_profile = new QComboBox(this);
    m_profile->setObjectName(QStringLiteral("brushProfileComboBox"));
    m_profile->addItem(tr("Smooth"), latin1(deform::falloffProfileName(deform::FalloffProfile::Smooth)));
    m_profile->addItem(tr("Linear"), latin1(deform::falloffProfileName(deform::FalloffProfile::Linear)));
    m_profile->addItem(tr("Sharp"), latin1(deform::falloffProfileName(deform::FalloffProfile::Sharp)));
    m_profile->setToolTip(tr("How the displacement falls off from the grabbed point to the radius."));
    form->addRow(tr("Falloff"), m_profile);
    m_iterations = new QSpinBox(this);
    m_iterations->setObjectName(QStringLiteral("brushIterationsSpinBox"));
    m_iterations->setRange(0, BrushChoices::kMaxIterations);
    m_iterations->setToolTip(tr("Laplacian smoothing iterations after the warp, restricted to the region."));
    form->addRow(tr("Smoothing iterations"), m_iterations);
    m_weights = new QComboBox(this);
    m_weights->setObjectName(QStringLiteral("brushWeightsComboBox"));
    m_weights->addItem(tr("Uniform"), latin1(deform::smoothingWeightsName(deform::SmoothingWeights::Uniform)));
    m_weights->addItem(tr("Cotangent"), latin1(deform::smoothingWeightsName(deform::SmoothingWeights::Cotangent)));
    m_weights->setToolTip(tr("Uniform: average of the neighbours (fast). Cotangent: shape-aware weights."));
    form->addRow(tr("Smoothing weights"), m_weights);
    m_step = new QDoubleSpinBox(this);
    m_step->setObjectName(QStringLiteral("brushStepSpinBox"));
    m_step->setRange(0.01, 1.0);
    m_step->setSingleStep(0.05);
    m_step->setToolTip(tr("λ of one smoothing step, p ← p + λ·L(p)."));
    form->addRow(tr("Smoothing step"), m_step);
    m_hint = new QLabel(tr("Brush (B): left drag deforms, Shift: along the normal; Alt+left, right or middle drag "
                           "move the camera."),
                        this);
    m_hint->setWordWrap(true);
    layout->addWidget(m_hint);
    layout->addStretch();
    connect(m_radius, &QDoubleSpinBox::valueChanged, this, &BrushPanel::onRadiusEdited);
    connect(m_strength, &QDoubleSpinBox::valueChanged, this, &BrushPanel::choicesChanged);
    connect(m_profile, &QComboBox::currentIndexChanged, this, &BrushPanel::choicesChanged);
    connect(m_iterations, &QSpinBox::valueChanged, this, &BrushPanel::choicesChanged);
    connect(m_weights, &QComboBox::currentIndexChanged, this, &BrushPanel::choicesChanged);
    connect(m_step, &QDoubleSpinBox::valueChanged, this, &BrushPanel::choicesChanged);
}

void BrushPanel::setChoices(const BrushChoices& choices)
{
    const QSignalBlocker b1(m_radius), b2(m_strength), b3(m_profile), b4(m_iterations), b5(m_weights), b6(m_step);
    m_radiusFraction = choices.radiusFraction;
    if (m_meshRadius > 0.0)
        m_radius->setValue(m_radiusFraction * m_meshRadius);
    m_strength->setValue(choices.settings.strength);
    m_profile->setCurrentIndex(m_profile->findData(latin1(deform::falloffProfileName(choices.settings.profile))));
    m_iterations->setValue(choices.settings.smoothingIterations);
    m_weights->setCurrentIndex(
        m_weights->findData(latin1(deform::smoothingWeightsName(choices.settings.smoothingWeights))));
    m_step->setValue(choices.settings.smoothingStep);
}

BrushChoices BrushPanel::choices() const
{
    BrushChoices choices;
    choices.radiusFraction = m_radiusFraction;
    choices.settings = settings();
    return choices;
}

void BrushPanel::setMeshRadius(double boundingRadius)
{
    const QSignalBlocker blocker(m_radius);
    m_meshRadius = boundingRadius > 0.0 && std::isfinite(boundingRadius) ? boundingRadius : 0.0;
    setEnabled(m_meshRadius > 0.0);
    if (m_meshRadius == 0.0)
        return;
    m_radius->setDecimals(decimalsFor(m_meshRadius * BrushChoices::kMinRadiusFraction));
    m_radius->setRange(m_meshRadius * BrushChoices::kMinRadiusFraction,
                       m_meshRadius * BrushChoices::kMaxRadiusFraction);
    m_radius->setSingleStep(m_meshRadius * 0.01);
    m_radius->setValue(m_radiusFraction * m_meshRadius);
}

deform::BrushSettings BrushPanel::settings() const
{
    deform::BrushSettings settings;
    settings.radius = m_meshRadius > 0.0 ? m_radius->value() : settings.radius;
    settings.strength = m_strength->value();
    settings.profile =
        deform::parseFalloffProfile(m_profile->currentData().toString().toStdString()).value_or(settings.profile);
    settings.smoothingIterations = m_iterations->value();
    settings.smoothingWeights = deform::parseSmoothingWeights(m_weights->currentData().toString().toStdString())
                                    .value_or(settings.smoothingWeights);
    settings.smoothingStep = m_step->value();
    return settings;
}

void BrushPanel::onRadiusEdited()
{
    if (m_meshRadius > 0.0)
        m_radiusFraction = m_radius->value() / m_meshRadius;
    emit choicesChanged();
}

} // namespace trimlab::ui
