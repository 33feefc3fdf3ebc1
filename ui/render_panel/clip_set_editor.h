#pragma once
/// \file
/// The "Clipping planes" group of the Render panel: up to kMaxClipPlanes planes at once
/// (a ClipSet, e.g. a clipping box), together keeping the intersection of their kept
/// half-spaces. One row per plane — a check box that enables it, a radio button that
/// picks it for editing, and its equation — and below them the picked plane in a
/// ClipPlaneEditor (normal, presets, offset slider and exact offset, flip). "Box" sets
/// the six planes to the scene's bounds (ClipSet::box), slightly enlarged so that no
/// plane grazes the scene, and picks plane 1: each plane's offset then shrinks the box
/// from its side. "None" disables every plane. Plane 1 is the one plane of earlier
/// versions (TrimSettings::clip).

#include "core/trim/clip_set.h"

#include <QGroupBox>

#include <array>

class QCheckBox;
class QLabel;
class QRadioButton;

namespace trimlab::ui {

class ClipPlaneEditor;

class ClipSetEditor : public QGroupBox {
    Q_OBJECT
public:
    explicit ClipSetEditor(QWidget* parent = nullptr);

    /// Shows `set` without emitting clipSetChanged(); the picked plane stays.
    void setClipSet(const ClipSet& set);
    /// The edited planes (a plane with a zero normal is reported disabled).
    [[nodiscard]] ClipSet clipSet() const { return m_planes; }

    /// The bounds the offset sliders span and the box presets.
    void setSceneBounds(const Bounds& bounds);
    /// Picks plane `index` (0 .. kMaxClipPlanes − 1) for the editor below; others ignored.
    void selectPlane(int index);
    [[nodiscard]] int selectedPlane() const { return m_selected; }
    /// The editor of the picked plane.
    [[nodiscard]] ClipPlaneEditor* planeEditor() const { return m_editor; }
    /// The picked plane along `normal` through the scene centre (the "View" preset's answer).
    void setNormalThroughCenter(const glm::dvec3& normal);
    /// The "Box" button's action: six enabled planes around the scene bounds; emits
    /// clipSetChanged(). Nothing happens without valid bounds.
    void setBoxAroundScene();

    /// How much the box preset enlarges the scene bounds on each side, as a fraction of
    /// the bounds' diagonal (planes through extreme vertices would decide their pixels
    /// by rounding).
    static constexpr double kBoxMargin = 1e-3;

signals:
    /// Any user edit of any plane.
    void clipSetChanged();
    /// The "View" preset was pressed: the owner answers with setNormalThroughCenter().
    void viewDirectionRequested();

private:
    QWidget* createPlaneRows();
    QWidget* createButtonRow();
    void onEditorChanged();
    void onRowToggled(int index, bool enabled);
    void disableAll();
    void refreshRows();

    ClipSet m_planes;
    int m_selected = 0;
    Bounds m_bounds;
    std::array<QCheckBox*, kMaxClipPlanes> m_enabled{};
    std::array<QRadioButton*, kMaxClipPlanes> m_pick{};
    std::array<QLabel*, kMaxClipPlanes> m_equation{};
    ClipPlaneEditor* m_editor = nullptr;
};

} // namespace trimlab::ui
