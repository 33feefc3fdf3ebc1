#pragma once
/// \file
/// Reading and writing the Skeleton panel's choices (keys "skeleton/…": the contraction
/// weights, caps and iterations, ordering and solver by their command-line names (amd,
/// colamd, metis; cholmod, ldlt), δ, w_a, w_b, refine, nodes, root, c, skinning lbs|dqs)
/// in a QSettings. Missing or unusable values fall back to SkeletonChoices' defaults,
/// field by field.

#include "ui/skeleton/skeleton_choices.h"

class QSettings;

namespace trimlab::ui {

[[nodiscard]] SkeletonChoices loadSkeletonChoices(const QSettings& settings);
void saveSkeletonChoices(QSettings& settings, const SkeletonChoices& choices);

} // namespace trimlab::ui
