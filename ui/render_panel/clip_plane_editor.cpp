#include "ui/render_panel/clip_plane_editor.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QToolButton>

#include <algorithm>
#include <cmath>

namespace trimlab::ui {

namespace {

constexpr int kSliderSteps = 1000;
constexpr double kOffsetLimit = 1e9;

/// Offsets at which the plane with `normal` touches the bounding sphere of `bounds`:
/// n·x + offset = 0 for x = c ± r n/|n|, i.e. offset = −n·c ∓ r|n|.
std::pair<double, double> offsetSpan(const glm::dvec3& normal, const Bounds& bounds)
{
    const glm::dvec3 center = bounds.valid() ? bounds.center() : glm::dvec3(0.0);
    const double radius = bounds.valid() ? std::max(bounds.radius(), 1e-6) : 1.0;
    const double length = std::max(glm::length(normal), 1e-12);
    const double middle = -glm::dot(normal, center);
    return {middle - radius * length, middle + radius * length};
}

QDoubleSpinBox* createComponentSpin(const QString& axis, QWidget* parent)
{
    auto* spin = new QDoubleSpinBox(parent);
    spin->setObjectName(QStringLiteral("clipNormal") + axis);
    spin->setRange(-1.0, 1.0);
    spin->setDecimals(3);
    spin->setSingleStep(0.1);
    spin->setPrefix(axis.toLower() + QStringLiteral(" "));
    spin->setToolTip(QObject::tr("%1 component of the plane normal (need not be unit length)").arg(axis));
    return spin;
}

} // namespace

ClipPlaneEditor::ClipPlaneEditor(QWidget* parent) : QGroupBox(tr("Clipping plane"), parent)
{
    setObjectName(QStringLiteral("clipGroup"));
    setCheckable(true);
    setChecked(false);
    setToolTip(tr("Cut the scene with the plane n·x + offset = 0, keeping the side n·x + offset ≥ 0. The winding "
                  "index is counted exactly, so the trimmed interior stays correct behind the cut."));
    auto* form = new QFormLayout(this);
    form->setRowWrapPolicy(QFormLayout::WrapLongRows); // a narrow dock puts the label above its row
    form->addRow(tr("Normal"), createNormalRow());
    form->addRow(tr("Presets"), createPresetRow());
    form->addRow(tr("Offset"), createOffsetRow());
    auto* flipButton = new QPushButton(tr("Flip"), this);
    flipButton->setObjectName(QStringLiteral("clipFlipButton"));
    flipButton->setToolTip(tr("Keep the other side of the plane"));
    connect(flipButton, &QPushButton::clicked, this, &ClipPlaneEditor::flip);
    form->addRow(QString(), flipButton);
    connect(this, &QGroupBox::toggled, this, &ClipPlaneEditor::planeChanged);
    setNormalSilently({0.0, 0.0, -1.0});
    updateOffsetRange();
}

QWidget* ClipPlaneEditor::createNormalRow()
{
    auto* row = new QWidget(this);
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    const QString axes[3] = {QStringLiteral("X"), QStringLiteral("Y"), QStringLiteral("Z")};
    for (int i = 0; i < 3; ++i) {
        m_normal[std::size_t(i)] = createComponentSpin(axes[i], row);
        layout->addWidget(m_normal[std::size_t(i)]);
        connect(m_normal[std::size_t(i)], &QDoubleSpinBox::valueChanged, this, &ClipPlaneEditor::onNormalEdited);
    }
    return row;
}

QWidget* ClipPlaneEditor::createPresetRow()
{
    auto* row = new QWidget(this);
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addWidget(createPresetButton(QStringLiteral("+X"), {1.0, 0.0, 0.0}));
    layout->addWidget(createPresetButton(QStringLiteral("−X"), {-1.0, 0.0, 0.0}));
    layout->addWidget(createPresetButton(QStringLiteral("+Y"), {0.0, 1.0, 0.0}));
    layout->addWidget(createPresetButton(QStringLiteral("−Y"), {0.0, -1.0, 0.0}));
    layout->addWidget(createPresetButton(QStringLiteral("+Z"), {0.0, 0.0, 1.0}));
    layout->addWidget(createPresetButton(QStringLiteral("−Z"), {0.0, 0.0, -1.0}));
    auto* view = new QToolButton(row);
    view->setText(tr("View"));
    view->setObjectName(QStringLiteral("clipPresetView"));
    view->setToolTip(tr("Normal along the current view direction: cuts away the half of the scene facing the camera"));
    connect(view, &QToolButton::clicked, this, &ClipPlaneEditor::viewDirectionRequested);
    layout->addWidget(view);
    layout->addStretch();
    return row;
}

QToolButton* ClipPlaneEditor::createPresetButton(const QString& text, const glm::dvec3& normal)
{
    auto* button = new QToolButton(this);
    button->setText(text);
    // Object names use ASCII signs ("clipPreset-X") so tests can find them.
    button->setObjectName(QStringLiteral("clipPreset") + QString(text).replace(QChar(0x2212), QLatin1Char('-')));
    button->setToolTip(tr("Normal %1 through the scene centre").arg(text));
    connect(button, &QToolButton::clicked, this, [this, normal] { setNormalThroughCenter(normal); });
    return button;
}

QWidget* ClipPlaneEditor::createOffsetRow()
{
    auto* row = new QWidget(this);
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    m_offsetSlider = new QSlider(Qt::Horizontal, row);
    m_offsetSlider->setObjectName(QStringLiteral("clipOffsetSlider"));
    m_offsetSlider->setRange(0, kSliderSteps);
    m_offsetSlider->setToolTip(tr("Sweeps the plane across the scene's bounding sphere"));
    m_offsetSpin = new QDoubleSpinBox(row);
    m_offsetSpin->setObjectName(QStringLiteral("clipOffsetSpin"));
    m_offsetSpin->setRange(-kOffsetLimit, kOffsetLimit);
    m_offsetSpin->setDecimals(4);
    // Its ±1e9 range made it as wide as its longest value and left the slider 80 pixels
    // to sweep the whole model: it gets room for realistic offsets, the slider the rest.
    m_offsetSpin->setMaximumWidth(m_offsetSpin->fontMetrics().horizontalAdvance(QStringLiteral("−0000.0000")) + 36);
    layout->addWidget(m_offsetSlider, 1);
    layout->addWidget(m_offsetSpin);
    connect(m_offsetSlider, &QSlider::valueChanged, this, &ClipPlaneEditor::onSliderMoved);
    connect(m_offsetSpin, &QDoubleSpinBox::valueChanged, this, &ClipPlaneEditor::onOffsetSpinEdited);
    return row;
}

glm::dvec3 ClipPlaneEditor::normal() const
{
    return {m_normal[0]->value(), m_normal[1]->value(), m_normal[2]->value()};
}

ClipPlane ClipPlaneEditor::plane() const
{
    ClipPlane plane;
    plane.normal = normal();
    plane.offset = m_offsetSpin->value();
    plane.enabled = isChecked() && plane.normal != glm::dvec3(0.0);
    return plane;
}

void ClipPlaneEditor::setPlane(const ClipPlane& plane)
{
    // The spin boxes hold components in [−1, 1]; scaling normal and offset together
    // keeps the same plane.
    const glm::dvec3 magnitude = glm::abs(plane.normal);
    const double scale = std::max({1.0, magnitude.x, magnitude.y, magnitude.z});
    const QSignalBlocker blocker(this);
    setChecked(plane.enabled);
    setNormalSilently(plane.normal / scale);
    setOffsetSilently(plane.offset / scale);
    updateOffsetRange();
}

void ClipPlaneEditor::setSceneBounds(const Bounds& bounds)
{
    m_bounds = bounds;
    updateOffsetRange();
}

void ClipPlaneEditor::setNormalThroughCenter(const glm::dvec3& normal)
{
    const double length = glm::length(normal);
    if (!std::isfinite(length) || length == 0.0)
        return;
    // Spin boxes hold components in [−1, 1]: store the unit normal.
    const glm::dvec3 unit = normal / length;
    const glm::dvec3 center = m_bounds.valid() ? m_bounds.center() : glm::dvec3(0.0);
    setNormalSilently(unit);
    setOffsetSilently(-glm::dot(unit, center));
    updateOffsetRange();
    emit planeChanged();
}

void ClipPlaneEditor::setNormalSilently(const glm::dvec3& normal)
{
    for (int i = 0; i < 3; ++i) {
        const QSignalBlocker blocker(m_normal[std::size_t(i)]);
        m_normal[std::size_t(i)]->setValue(normal[i]);
    }
}

void ClipPlaneEditor::setOffsetSilently(double offset)
{
    const QSignalBlocker blocker(m_offsetSpin);
    m_offsetSpin->setValue(offset);
}

void ClipPlaneEditor::updateSliderFromOffset()
{
    const auto [low, high] = offsetSpan(normal(), m_bounds);
    const double fraction = (m_offsetSpin->value() - low) / (high - low);
    const QSignalBlocker blocker(m_offsetSlider);
    m_offsetSlider->setValue(int(std::lround(std::clamp(fraction, 0.0, 1.0) * kSliderSteps)));
}

void ClipPlaneEditor::updateOffsetRange()
{
    // Not on offset edits: setSingleStep rewrites the spin box text while the user types.
    const auto [low, high] = offsetSpan(normal(), m_bounds);
    m_offsetSpin->setSingleStep((high - low) / 100.0);
    updateSliderFromOffset();
}

void ClipPlaneEditor::onNormalEdited()
{
    updateOffsetRange();
    emit planeChanged();
}

void ClipPlaneEditor::onOffsetSpinEdited()
{
    updateSliderFromOffset();
    emit planeChanged();
}

void ClipPlaneEditor::onSliderMoved(int position)
{
    const auto [low, high] = offsetSpan(normal(), m_bounds);
    setOffsetSilently(low + (high - low) * double(position) / kSliderSteps);
    emit planeChanged();
}

void ClipPlaneEditor::flip()
{
    const ClipPlane flipped = plane().flipped();
    setNormalSilently(flipped.normal);
    setOffsetSilently(flipped.offset);
    updateOffsetRange();
    emit planeChanged();
}

} // namespace trimlab::ui
