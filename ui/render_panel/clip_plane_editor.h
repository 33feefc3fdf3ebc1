#pragma once
/// \file
/// The editor of one clipping plane (the plane picked in the Render panel's clip set
/// editor, clip_set_editor.h): a checkable group box editing a ClipPlane (n·x + offset ≥ 0
/// is kept). The normal is three spin boxes plus presets
/// (±X, ±Y, ±Z, and the current view direction, which the owner supplies on request);
/// presets put the plane through the centre of the scene bounds. The offset has a slider
/// spanning the offsets at which the plane touches the scene's bounding sphere, and a
/// spin box for exact (also out-of-range) values. Flip keeps the other side.

#include "core/trim/clip_plane.h"

#include <QGroupBox>

#include <array>

class QDoubleSpinBox;
class QSlider;
class QToolButton;

namespace trimlab::ui {

class ClipPlaneEditor : public QGroupBox {
    Q_OBJECT
public:
    explicit ClipPlaneEditor(QWidget* parent = nullptr);

    /// Shows `plane` without emitting planeChanged().
    void setPlane(const ClipPlane& plane);
    /// The edited plane. A zero normal clips nothing: the plane is then reported disabled.
    [[nodiscard]] ClipPlane plane() const;

    /// The bounds the offset slider spans (an invalid box: the unit sphere at the origin).
    void setSceneBounds(const Bounds& bounds);
    /// Sets the normal and moves the plane through the centre of the scene bounds; emits
    /// planeChanged(). A zero or non-finite normal is ignored.
    void setNormalThroughCenter(const glm::dvec3& normal);

signals:
    /// Any user edit of the plane (enable, normal, offset, flip, presets).
    void planeChanged();
    /// The "View" preset was pressed: the owner answers with setNormalThroughCenter().
    void viewDirectionRequested();

private:
    QWidget* createNormalRow();
    QWidget* createPresetRow();
    QWidget* createOffsetRow();
    QToolButton* createPresetButton(const QString& text, const glm::dvec3& normal);
    [[nodiscard]] glm::dvec3 normal() const;
    void setNormalSilently(const glm::dvec3& normal);
    void setOffsetSilently(double offset);
    void updateSliderFromOffset();
    void updateOffsetRange();
    void onNormalEdited();
    void onOffsetSpinEdited();
    void onSliderMoved(int position);
    void flip();

    std::array<QDoubleSpinBox*, 3> m_normal{};
    QSlider* m_offsetSlider = nullptr;
    QDoubleSpinBox* m_offsetSpin = nullptr;
    Bounds m_bounds;
};

} // namespace trimlab::ui
