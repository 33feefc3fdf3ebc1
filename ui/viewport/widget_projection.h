#pragma once
/// \file
/// Where the overlays over the viewport (viewport_overlay.h: the skeleton, the control
/// net) and their tools see points and segments: world points projected with the
/// viewport's camera into logical widget coordinates (x right, y down, origin at the
/// top-left corner), and the segment (a bone) nearest to a cursor position.

#include "core/view/camera.h"

#include <QPointF>
#include <QSizeF>

#include <glm/vec3.hpp>

#include <array>
#include <optional>
#include <span>
#include <vector>

namespace trimlab::ui {

/// `world` on a widget of `size` (logical pixels) seen through `camera` (its aspect is
/// the widget's). nullopt for a point behind or on the eye plane (clip w ≤ 0), or a
/// non-finite one, or an empty widget. Points outside the view project outside the rect.
[[nodiscard]] std::optional<QPointF> projectToWidget(const Camera& camera, QSizeF size, const glm::dvec3& world);

/// The distance from `p` to the segment a–b (a point when a == b), in the same units.
[[nodiscard]] double distanceToSegment(QPointF p, QPointF a, QPointF b);

/// The index of the segment (bones[i] = {head, tail} into `points`, projected joints)
/// nearest to `cursor` within `maxDistance`, or −1. Bones with an unprojected end are
/// skipped; ties go to the lower index.
[[nodiscard]] int nearestSegment(QPointF cursor, std::span<const std::optional<QPointF>> points,
                                 std::span<const std::array<int, 2>> bones, double maxDistance);

} // namespace trimlab::ui
