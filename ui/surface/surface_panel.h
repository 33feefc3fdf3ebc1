#pragma once
/// \file
/// The Surface panel (content of the "Surface" dock): what the shown editable surface is
/// and its parameters — NURBS: tessellation density along u and v, patch degree;
/// subdivision: scheme (Catmull–Clark / Loop), level 0–5, uniform or limit positions —,
/// "Show control net", the selection (how many control points), and "Move along normal"
/// for the selected points (a distance in the surface's units and a button).
///
/// The density, level, scheme and mode change the tessellation's connectivity, which a
/// history keeps fixed across its frames; the panel only reports the edit
/// (parametersEdited) and the owner rebuilds the surface (or refuses and calls
/// setChoices() to put the old values back). The panel holds no surface.

#include "ui/surface/surface_settings_store.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace trimlab::ui {

class SurfacePanel : public QWidget {
    Q_OBJECT
public:
    /// What kind of surface the session edits (the groups enabled follow it).
    enum class Kind { None, Nurbs, NurbsPatch, Subdivision };

    explicit SurfacePanel(QWidget* parent = nullptr);

    /// Shows `choices` without emitting any signal.
    void setChoices(const SurfaceChoices& choices);
    [[nodiscard]] SurfaceChoices choices() const;
    /// The surface shown: its kind, a one-line description ("NURBS sphere: 9 × 5 control
    /// points, 1 024 triangles") and its bounding radius (> 0; scales the normal step).
    void setSurface(Kind kind, const QString& description, double boundingRadius);
    [[nodiscard]] Kind kind() const { return m_kind; }
    /// How many control points are selected (enables "Move along normal").
    void setSelectionCount(int count);

signals:
    /// A parameter that changes the tessellation (density, degree, scheme, level, mode).
    void parametersEdited();
    void showNetToggled(bool shown);
    /// "Move along normal" clicked: move the selection by `distance` (surface units).
    void moveAlongNormalRequested(double distance);
    /// Any user edit (for persistence).
    void choicesChanged();

private:
    void createControls();
    QGroupBox* createNurbsGroup();
    QGroupBox* createSubdivisionGroup();
    QGroupBox* createSelectionGroup();
    void updateEnabled();

    QLabel* m_description = nullptr;
    QGroupBox* m_nurbsGroup = nullptr;
    QSpinBox* m_segmentsU = nullptr;
    QSpinBox* m_segmentsV = nullptr;
    QSpinBox* m_degree = nullptr;
    QGroupBox* m_subdivisionGroup = nullptr;
    QComboBox* m_scheme = nullptr;
    QSpinBox* m_level = nullptr;
    QComboBox* m_mode = nullptr;
    QCheckBox* m_showNet = nullptr;
    QLabel* m_selection = nullptr;
    QDoubleSpinBox* m_normalStep = nullptr;
    QPushButton* m_moveAlongNormal = nullptr;
    Kind m_kind = Kind::None;
    double m_radius = 0.0;
    double m_normalStepFraction = SurfaceChoices{}.normalStepFraction;
    int m_selectionCount = 0;
};

} // namespace trimlab::ui
