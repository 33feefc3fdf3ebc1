#include "ui/skinning/skinning_bone_editor.h"

#include "ui/common/undo_buttons.h"

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPixmap>
#include <QPushButton>
#include <QVBoxLayout>

#include <cmath>

namespace trimlab::ui {

namespace {

constexpr int kSwatchSize = 12;
constexpr double kLengthRange = 10.0; ///< translations up to ± this many length scales
constexpr double kStepsPerLength = 100.0;

QIcon swatch(const WheelColor& color)
{
    const glm::vec3 rgb = color.rgb();
    QPixmap pixmap(kSwatchSize, kSwatchSize);
    pixmap.fill(QColor::fromRgbF(rgb.r, rgb.g, rgb.b));
    return QIcon(pixmap);
}

QDoubleSpinBox* spinBox(const QString& name, double range, double step, int decimals, const QString& suffix)
{
    auto* box = new QDoubleSpinBox;
    box->setObjectName(name);
    box->setRange(-range, range);
    box->setSingleStep(step);
    box->setDecimals(decimals);
    box->setSuffix(suffix);
    box->setAccelerated(true);
    return box;
}

} // namespace

SkinningBoneEditor::SkinningBoneEditor(QWidget* parent) : QWidget(parent)
{
    m_bones = new QListWidget;
    m_bones->setObjectName(QStringLiteral("skinningBoneList"));
    m_bones->setToolTip(tr("The proxy bones: one per segment, in the segment's color"));
    m_bones->setMaximumHeight(140);
    m_pose = new QLabel;
    m_pose->setObjectName(QStringLiteral("skinningEditPoseLabel"));
    m_pose->setWordWrap(true);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_bones);
    layout->addWidget(m_pose);
    layout->addWidget(createTransformRows());
    layout->addWidget(createButtonRow());
    connect(m_bones, &QListWidget::currentRowChanged, this, &SkinningBoneEditor::updateButtons);
    setLengthScale(1.0);
    setPose(0, false);
}

QWidget* SkinningBoneEditor::createTransformRows()
{
    auto* rows = new QWidget;
    auto* grid = new QGridLayout(rows);
    grid->setContentsMargins(0, 0, 0, 0);
    const char* axes[3] = {"X", "Y", "Z"};
    grid->addWidget(new QLabel(tr("Rotate")), 0, 0);
    grid->addWidget(new QLabel(tr("Move")), 1, 0);
    for (int axis = 0; axis < 3; ++axis) {
        m_rotation[axis] = spinBox(QStringLiteral("boneRotate%1SpinBox").arg(QLatin1String(axes[axis])), 180.0, 5.0, 1,
                                   QStringLiteral("°"));
        m_rotation[axis]->setToolTip(tr("Degrees about the %1 axis through the bone's centroid").arg(axes[axis]));
        m_translation[axis] =
            spinBox(QStringLiteral("boneMove%1SpinBox").arg(QLatin1String(axes[axis])), 1.0, 0.01, 4, {});
        m_translation[axis]->setToolTip(tr("Translation along %1 in the animation's length units").arg(axes[axis]));
        grid->addWidget(m_rotation[axis], 0, axis + 1);
        grid->addWidget(m_translation[axis], 1, axis + 1);
    }
    return rows;
}

QWidget* SkinningBoneEditor::createButtonRow()
{
    m_apply = new QPushButton(tr("Apply"));
    m_apply->setObjectName(QStringLiteral("applyBoneEditButton"));
    m_apply->setToolTip(tr("Give the bone this extra motion at the shown pose; later poses follow (eq. 4.18), "
                           "earlier poses do not change"));
    m_undoButtons =
        new UndoButtons(QStringLiteral("undoSkinningEditButton"), QStringLiteral("redoSkinningEditButton"), this);
    connect(m_apply, &QPushButton::clicked, this, &SkinningBoneEditor::apply);
    auto* row = new QWidget;
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_apply);
    layout->addWidget(m_undoButtons->undoButton());
    layout->addWidget(m_undoButtons->redoButton());
    return row;
}

void SkinningBoneEditor::setBones(std::span<const WheelColor> colors)
{
    const int selected = selectedBone();
    m_bones->clear();
    for (std::size_t bone = 0; bone < colors.size(); ++bone)
        m_bones->addItem(new QListWidgetItem(swatch(colors[bone]), tr("Bone %1").arg(bone)));
    if (m_bones->count() > 0)
        m_bones->setCurrentRow(selected >= 0 && selected < m_bones->count() ? selected : 0);
    updateButtons();
}

void SkinningBoneEditor::setPose(int pose, bool editable, const QString& reason)
{
    m_editable = editable;
    m_pose->setText(reason.isEmpty() ? tr("Edits apply to pose %1 and carry to every later pose.").arg(pose) : reason);
    updateButtons();
}

void SkinningBoneEditor::setLengthScale(double length)
{
    const double scale = length > 0.0 && std::isfinite(length) ? length : 1.0;
    const double step = scale / kStepsPerLength;
    const int decimals = std::clamp(int(std::ceil(-std::log10(step))) + 1, 1, 8);
    for (QDoubleSpinBox* box : m_translation) {
        box->setDecimals(decimals);
        box->setRange(-kLengthRange * scale, kLengthRange * scale);
        box->setSingleStep(step);
    }
}

void SkinningBoneEditor::setUndoStack(QUndoStack* stack)
{
    m_undoButtons->setStack(stack);
}

int SkinningBoneEditor::selectedBone() const
{
    return m_bones->currentRow();
}

void SkinningBoneEditor::selectBone(int bone)
{
    m_bones->setCurrentRow(bone);
}

BoneEdit SkinningBoneEditor::edit() const
{
    BoneEdit edit;
    for (int axis = 0; axis < 3; ++axis) {
        edit.rotationDegrees[axis] = m_rotation[axis]->value();
        edit.translation[axis] = m_translation[axis]->value();
    }
    return edit;
}

void SkinningBoneEditor::apply()
{
    const int bone = selectedBone();
    if (!m_editable || bone < 0)
        return;
    const BoneEdit requested = edit();
    resetEdit();
    emit applyRequested(bone, requested);
}

void SkinningBoneEditor::resetEdit()
{
    for (int axis = 0; axis < 3; ++axis) {
        m_rotation[axis]->setValue(0.0);
        m_translation[axis]->setValue(0.0);
    }
}

void SkinningBoneEditor::updateButtons()
{
    const bool haveBone = selectedBone() >= 0;
    m_apply->setEnabled(m_editable && haveBone);
    for (QDoubleSpinBox* box : m_rotation)
        box->setEnabled(m_editable && haveBone);
    for (QDoubleSpinBox* box : m_translation)
        box->setEnabled(m_editable && haveBone);
}

} // namespace trimlab::ui
