#pragma once
/// \file
/// The Run / Cancel row of the panels that start long work in the background
/// (segmentation, skinning, skeleton; job_presenter.h keeps it in step with the job): two
/// buttons side by side, no margins.

class QPushButton;
class QWidget;

namespace trimlab::ui {

/// A new row widget holding `run` and `cancel` (which it adopts).
[[nodiscard]] QWidget* runCancelRow(QPushButton* run, QPushButton* cancel);

} // namespace trimlab::ui
