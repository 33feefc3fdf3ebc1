#pragma once
/// \file
/// The "what to fit" part of the Skinning panel: the bones (one per segment of the
/// segmentation shown in the Segmentation panel, whose number is shown here, or a given
/// number B), the skinning method (LBS/DQS), the chain (pose-to-pose or rest-to-pose) and the weight and
/// vertex corrections. Emits changed() on every user edit.

#include "ui/skinning/skinning_choices.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QSpinBox;

namespace trimlab::ui {

class SkinningSettingsForm : public QWidget {
    Q_OBJECT
public:
    explicit SkinningSettingsForm(QWidget* parent = nullptr);

    /// Shows `choices` without emitting changed().
    void setChoices(const SkinningChoices& choices);
    [[nodiscard]] SkinningChoices choices() const;
    /// The bone count the segmentation gives (0: no segmentation yet).
    void setSegmentCount(std::size_t count);

signals:
    void changed();

private:
    void updateBoneCountEnabled();
    void updateChainEnabled();

    QComboBox* m_boneSource = nullptr;
    QSpinBox* m_boneCount = nullptr;
    QLabel* m_bones = nullptr;
    QComboBox* m_method = nullptr;
    SkinningChain m_chosenChain = SkinningChain::PoseToPose; ///< for LBS and DQS (the rigid fit has none)
    QComboBox* m_chain = nullptr;
    QCheckBox* m_weightCorrections = nullptr;
    QCheckBox* m_vertexCorrections = nullptr;
    QSpinBox* m_influences = nullptr;
};

} // namespace trimlab::ui
