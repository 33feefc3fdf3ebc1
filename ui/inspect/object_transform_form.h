#pragma once
/// \file
/// Numeric entry of one object's transform (core/scene/object_transform.h): translation
/// x, y, z (world units), rotation about x, y, z (degrees, applied in that order, wrapping
/// at ±180°) and a uniform scale (> 0). An edit changes only its own component (the
/// others keep full precision, not the fields' rounding). A value commits on Return or when its field loses
/// focus, and at every arrow step; "Reset" returns to the identity.

#include "core/scene/object_transform.h"

#include <QWidget>

#include <array>

class QDoubleSpinBox;
class QPushButton;

namespace trimlab::ui {

class ObjectTransformForm : public QWidget {
    Q_OBJECT
public:
    explicit ObjectTransformForm(QWidget* parent = nullptr);

    /// Shows `transform` without emitting transformEdited().
    void setTransform(const ObjectTransform& transform);
    [[nodiscard]] ObjectTransform transform() const;
    /// The step of the translation fields (e.g. a fiftieth of the scene radius); > 0.
    void setTranslationStep(double step);

signals:
    /// The user changed a field or pressed Reset.
    void transformEdited(const trimlab::ObjectTransform& transform);

private:
    /// A field editing component `component` (0..6: tx ty tz rx ry rz scale).
    QDoubleSpinBox* addSpin(int component, const QString& objectName, const QString& prefix, const QString& toolTip);
    void onFieldEdited(int component, double value);

    std::array<QDoubleSpinBox*, 3> m_translation{};
    std::array<QDoubleSpinBox*, 3> m_rotation{};
    QDoubleSpinBox* m_scale = nullptr;
    QPushButton* m_reset = nullptr;
    /// The transform shown, at full precision: an edit replaces only its own component,
    /// so the fields' rounding never leaks into the others.
    ObjectTransform m_shown;
};

} // namespace trimlab::ui
