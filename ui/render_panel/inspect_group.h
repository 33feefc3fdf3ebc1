#pragma once
/// \file
/// The "Capping and highlighting" group of the Render panel (interior inspection, thesis
/// 8.1.2): caps where a clipping plane cuts into the solid — on/off, the pattern
/// (hatched, striped, solid) and the line spacing as a percentage of the scene's
/// bounding radius — and the tints of the shown fragments: collisions (inside another
/// object, or where an object overlaps itself) and coplanar fragments (colored by the
/// size of their group). The status bar counts the highlighted pixels of each frame.
/// X-ray (TransparencySettings): off, "Opaque trim + ghosts" (the trimmed solid as usual,
/// the fragments the trim removed in front of it as translucent ghosts) or "Translucent"
/// (every boundary of the trimmed solid a translucent layer), with the layer and ghost
/// opacities, the density inside the solid (per world unit) and the Fresnel exponent.

#include "core/trim/inspect_settings.h"

#include <QGroupBox>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;

namespace trimlab::ui {

class InspectGroup : public QGroupBox {
    Q_OBJECT
public:
    explicit InspectGroup(QWidget* parent = nullptr);

    /// Shows the choices without emitting changed(). cap.spacing is ignored (the spacing
    /// is `spacingFraction` of the scene radius; out-of-range values are clamped).
    void setChoices(const CapSettings& cap, double spacingFraction, const HighlightSettings& highlight);
    /// Capping on/off and pattern (spacing and line width at their defaults: see
    /// spacingFraction()).
    [[nodiscard]] CapSettings cap() const;
    /// The line spacing as a fraction of the scene's bounding radius.
    [[nodiscard]] double spacingFraction() const;
    [[nodiscard]] HighlightSettings highlight() const;
    /// Shows the X-ray choices without emitting changed() (values clamped to the ranges
    /// of the spin boxes).
    void setTransparency(const TransparencySettings& transparency);
    [[nodiscard]] TransparencySettings transparency() const;
    /// Why nothing in the group applies now ("" when it does): the controls are disabled,
    /// keeping their choices, and a line in the group says why.
    void setUnavailableReason(const QString& reason);

signals:
    /// Any user edit.
    void changed();

private:
    QWidget* createCapRows();
    QWidget* createXrayRows();
    void updateEnabled();

    QLabel* m_unavailable = nullptr;
    QCheckBox* m_cap = nullptr;
    QComboBox* m_pattern = nullptr;
    QDoubleSpinBox* m_spacing = nullptr;
    QCheckBox* m_collisions = nullptr;
    QCheckBox* m_coplanar = nullptr;
    QComboBox* m_xrayMode = nullptr;
    QDoubleSpinBox* m_layerAlpha = nullptr;
    QDoubleSpinBox* m_ghostAlpha = nullptr;
    QDoubleSpinBox* m_density = nullptr;
    QDoubleSpinBox* m_fresnel = nullptr;
};

} // namespace trimlab::ui
