#pragma once
/// \file
/// The pose-editing part of the Skinning panel (thesis 4.1.3): the bones (one per segment,
/// in the segment's color), a rotation about the chosen bone's centroid and a
/// translation, Apply — which asks for the edit of that bone at the pose the timeline
/// shows (applyRequested()) — and Undo/Redo of the edits on the session's undo stack.
/// The spin boxes hold the change to apply, not the bone's transform: Apply resets them.

#include "core/skinning/bone_edit.h"

#include "core/animation/color_wheel.h"

#include <QWidget>

#include <span>

class QDoubleSpinBox;
class QLabel;
class QListWidget;
class QPushButton;
class QUndoStack;

namespace trimlab::ui {

class UndoButtons;

class SkinningBoneEditor : public QWidget {
    Q_OBJECT
public:
    explicit SkinningBoneEditor(QWidget* parent = nullptr);

    /// Lists one bone per color (none: nothing to edit). Keeps the selected row if valid.
    void setBones(std::span<const WheelColor> colors);
    /// The pose edits apply to; `editable` false disables Apply and shows `reason`.
    void setPose(int pose, bool editable, const QString& reason = {});
    /// The translation spin boxes' step: `length` / 100 (e.g. the animation's diagonal).
    void setLengthScale(double length);
    /// The stack Undo/Redo act on and reflect (nullptr: both disabled).
    void setUndoStack(QUndoStack* stack);

    /// The selected bone, or −1.
    [[nodiscard]] int selectedBone() const;
    void selectBone(int bone);
    /// What the spin boxes hold.
    [[nodiscard]] BoneEdit edit() const;

signals:
    void applyRequested(int bone, const trimlab::BoneEdit& edit);

private:
    QWidget* createTransformRows();
    QWidget* createButtonRow();
    void apply();
    void resetEdit();
    void updateButtons();

    QListWidget* m_bones = nullptr;
    QLabel* m_pose = nullptr;
    QDoubleSpinBox* m_rotation[3] = {};
    QDoubleSpinBox* m_translation[3] = {};
    QPushButton* m_apply = nullptr;
    UndoButtons* m_undoButtons = nullptr;
    bool m_editable = false;
};

} // namespace trimlab::ui
