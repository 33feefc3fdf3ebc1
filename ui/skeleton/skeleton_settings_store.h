#pragma once
/// \file
/// Reading and writing the Skeleton panel's choices in a QSettings, each at its row's key
/// of core/skeleton/skeleton_parameters.h ("skeleton/…": the contraction weights, caps and
/// iterations, ordering and solver by their command-line names, δ, w_a, w_b, refine,
/// nodes, root, c, skinning lbs|dqs). Missing or unusable values fall back to the rows'
/// defaults, field by field (ui/common/parameter_settings.h).

#include "ui/skeleton/skeleton_choices.h"

class QSettings;

namespace trimlab::ui {

[[nodiscard]] SkeletonChoices loadSkeletonChoices(const QSettings& settings);
void saveSkeletonChoices(QSettings& settings, const SkeletonChoices& choices);

} // namespace trimlab::ui
