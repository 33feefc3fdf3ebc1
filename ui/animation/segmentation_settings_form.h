#pragma once
/// \file
/// The "what to compute" part of the Segmentation panel: the per-pose feature (rotation
/// angle, velocity, acceleration), the reference pose of the rotation angle (rest or
/// previous), the clustering method and clusters per pose, worker threads, and the mode
/// (global, real-time, variable). Emits changed() on every user edit.

#include "ui/animation/segmentation_choices.h"

#include <QWidget>

class QComboBox;
class QSpinBox;

namespace trimlab::ui {

class SegmentationSettingsForm : public QWidget {
    Q_OBJECT
public:
    explicit SegmentationSettingsForm(QWidget* parent = nullptr);

    /// Shows the feature, reference, method, clusters, threads and mode of `choices`
    /// without emitting changed().
    void setChoices(const SegmentationChoices& choices);
    /// `choices` with this form's fields replaced by what is shown.
    [[nodiscard]] SegmentationChoices applyTo(SegmentationChoices choices) const;

signals:
    void changed();

private:
    void updateReferenceEnabled();

    QComboBox* m_feature = nullptr;
    QComboBox* m_reference = nullptr;
    QComboBox* m_method = nullptr;
    QSpinBox* m_clusters = nullptr;
    QSpinBox* m_threads = nullptr;
    QComboBox* m_mode = nullptr;
};

} // namespace trimlab::ui
