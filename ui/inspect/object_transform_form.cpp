#include "ui/inspect/object_transform_form.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QPushButton>
#include <QSignalBlocker>

#include <cmath>

namespace trimlab::ui {

namespace {

constexpr double kTranslationLimit = 1e6;
constexpr double kMaxScale = 1000.0;

QWidget* row(QWidget* parent, const std::array<QDoubleSpinBox*, 3>& spins)
{
    auto* widget = new QWidget(parent);
    auto* layout = new QHBoxLayout(widget);
    layout->setContentsMargins(0, 0, 0, 0);
    for (QDoubleSpinBox* spin : spins)
        layout->addWidget(spin);
    return widget;
}

} // namespace

ObjectTransformForm::ObjectTransformForm(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("objectTransformForm"));
    const char* axes[3] = {"X", "Y", "Z"};
    for (int i = 0; i < 3; ++i) {
        const QString axis = QString::fromLatin1(axes[i]);
        QDoubleSpinBox* move = addSpin(i, QStringLiteral("translate") + axis, axis.toLower() + QLatin1Char(' '),
                                       tr("Translation along world %1 (world units)").arg(axis));
        move->setRange(-kTranslationLimit, kTranslationLimit);
        move->setDecimals(4);
        m_translation[std::size_t(i)] = move;
        QDoubleSpinBox* turn = addSpin(3 + i, QStringLiteral("rotate") + axis, axis.toLower() + QLatin1Char(' '),
                                       tr("Rotation about world %1 in degrees (x first, then y, then z)").arg(axis));
        turn->setRange(-180.0, 180.0);
        turn->setWrapping(true);
        turn->setDecimals(2);
        turn->setSingleStep(5.0);
        turn->setSuffix(QStringLiteral("°"));
        m_rotation[std::size_t(i)] = turn;
    }
    m_scale =
        addSpin(6, QStringLiteral("uniformScale"), QString(), tr("Uniform scale about the object's origin (> 0)"));
    m_scale->setRange(0.001, kMaxScale);
    m_scale->setDecimals(4);
    m_scale->setSingleStep(0.05);
    m_reset = new QPushButton(tr("Reset"), this);
    m_reset->setObjectName(QStringLiteral("resetTransformButton"));
    m_reset->setToolTip(tr("Back to no translation, no rotation and scale 1"));
    connect(m_reset, &QPushButton::clicked, this, [this] {
        setTransform(ObjectTransform{});
        emit transformEdited(ObjectTransform{});
    });
    auto* form = new QFormLayout(this);
    form->setContentsMargins(0, 0, 0, 0);
    form->setRowWrapPolicy(QFormLayout::WrapAllRows); // labels above their fields: the rows fit a side dock
    form->addRow(tr("Translate"), row(this, m_translation));
    form->addRow(tr("Rotate"), row(this, m_rotation));
    auto* scaleRow = new QWidget(this);
    auto* scaleLayout = new QHBoxLayout(scaleRow);
    scaleLayout->setContentsMargins(0, 0, 0, 0);
    scaleLayout->addWidget(m_scale);
    scaleLayout->addStretch();
    scaleLayout->addWidget(m_reset);
    form->addRow(tr("Scale"), scaleRow);
    setTransform(ObjectTransform{});
}

QDoubleSpinBox* ObjectTransformForm::addSpin(int component, const QString& objectName, const QString& prefix,
                                             const QString& toolTip)
{
    auto* spin = new QDoubleSpinBox(this);
    spin->setObjectName(objectName);
    spin->setPrefix(prefix);
    spin->setToolTip(toolTip);
    // Typing "0.5" must not move the object to 0 first: commit on Return or focus out.
    spin->setKeyboardTracking(false);
    // Wide enough for a value of the size a scene has, not for the range's limit (a
    // million, 4 decimals): three of these and their label then fit a side dock without
    // scrolling it sideways; a longer value scrolls inside its box.
    constexpr int kArrowsAndFrame = 24;
    spin->setMinimumWidth(spin->fontMetrics().horizontalAdvance(prefix + QStringLiteral("-00.0000°")) +
                          kArrowsAndFrame);
    connect(spin, &QDoubleSpinBox::valueChanged, this,
            [this, component](double value) { onFieldEdited(component, value); });
    return spin;
}

void ObjectTransformForm::onFieldEdited(int component, double value)
{
    if (component < 3)
        m_shown.translation[component] = value;
    else if (component < 6)
        m_shown.rotationDegrees[component - 3] = value;
    else
        m_shown.scale = value;
    emit transformEdited(m_shown);
}

void ObjectTransformForm::setTransform(const ObjectTransform& transform)
{
    m_shown = transform;
    for (int i = 0; i < 3; ++i) {
        const QSignalBlocker moveBlocker(m_translation[std::size_t(i)]);
        const QSignalBlocker turnBlocker(m_rotation[std::size_t(i)]);
        m_translation[std::size_t(i)]->setValue(transform.translation[i]);
        m_rotation[std::size_t(i)]->setValue(transform.rotationDegrees[i]);
    }
    const QSignalBlocker scaleBlocker(m_scale);
    m_scale->setValue(transform.scale);
}

ObjectTransform ObjectTransformForm::transform() const
{
    return m_shown;
}

void ObjectTransformForm::setTranslationStep(double step)
{
    if (!(step > 0.0) || !std::isfinite(step))
        return;
    for (QDoubleSpinBox* spin : m_translation)
        spin->setSingleStep(step);
}

} // namespace trimlab::ui
