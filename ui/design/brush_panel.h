#pragma once
/// \file
/// The Brush panel (content of the "Brush" dock): the settings of the space-warp brush —
/// radius (geodesic, in mesh units), strength, falloff profile, and the Laplacian
/// smoothing that follows the warp (iterations, uniform or cotangent weights, step λ).
/// The radius is shown in the current mesh's units and kept as a fraction of its
/// bounding radius, so it scales when another mesh is opened (brush_settings_store.h).

#include "ui/design/brush_settings_store.h"
#include "core/deform/stroke.h"

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QSpinBox;

namespace trimlab::ui {

class BrushPanel : public QWidget {
    Q_OBJECT
public:
    explicit BrushPanel(QWidget* parent = nullptr);

    /// Shows `choices` without emitting choicesChanged() (toolEnabled is not shown here).
    void setChoices(const BrushChoices& choices);
    [[nodiscard]] BrushChoices choices() const;
    /// The bounding radius of the mesh the brush edits (> 0): the radius range and value
    /// follow it, keeping the fraction. 0: no mesh (the controls are disabled).
    void setMeshRadius(double boundingRadius);
    /// The brush settings for the current mesh (radius in mesh units).
    [[nodiscard]] deform::BrushSettings settings() const;

signals:
    /// Any user edit.
    void choicesChanged();

private:
    void createControls();
    void onRadiusEdited();

    QDoubleSpinBox* m_radius = nullptr;
    QDoubleSpinBox* m_strength = nullptr;
    QComboBox* m_profile = nullptr;
    QSpinBox* m_iterations = nullptr;
    QComboBox* m_weights = nullptr;
    QDoubleSpinBox* m_step = nullptr;
    QLabel* m_hint = nullptr;
    double m_meshRadius = 0.0;
    double m_radiusFraction = BrushChoices{}.radiusFraction;
};

} // namespace trimlab::ui
