#pragma once
/// \file
/// Scripted control-point histories of editable surfaces, shared by the render tests and
/// the demos: the thesis's Fig. 8.13 situation on a NURBS sphere (moving control points
/// pushes the surface through itself; the static rule shows the pushed part differently
/// from the dynamic rule) and a small subdivision-cube edit.

#include "core/timeline/timeline.h"

namespace trimlab {

/// The NURBS unit sphere (makeNurbsSphere at the origin, default tessellation) edited in
/// two sets of control-point edits, deterministic (same bits on every run):
///  - set 0 (`firstRule`): one edit pulls the control points of the +x side of the
///    equator outwards (a disjoint bump, as Fig. 8.13 b/c);
///  - set 1 (`secondRule`): three edits push the north pole (with its tied points) and
///    the ring of control points around it down through the sphere until the dent comes
///    out below the south side (Fig. 8.13 d–g).
/// The last frame is the one the figure renders. Frame count 5 (base + 4 edits).
/// What it shows (tests/render/tst_surface_replays.cpp): below the south pole the tip
/// encloses winding index −1. The parity rule calls that interior, so the static
/// rendering shows the tip as a bump; the dynamic rules (confluent, constructive
/// subtractive: the index there decreased) carve it, showing a hole through which the
/// dent's inside is seen. (Alternating border and positive index treat −1 as exterior,
/// like the dynamic rules, so with them this design shows no contrast; the thesis's own
/// sequence is longer.)
[[nodiscard]] timeline::Timeline fig8_13NurbsHistory(DynamicRule firstRule = DynamicRule::Confluent,
                                                     DynamicRule secondRule = DynamicRule::Confluent);

/// The Catmull–Clark cube cage (cubeCage(0.8)), level 3, limit mode, one set of `rule`
/// with one edit that pushes the cage corner (+0.8, +0.8, +0.8) to (0, −1.2, 0): through
/// the body and out below the bottom.
[[nodiscard]] timeline::Timeline subdivisionPushHistory(DynamicRule rule = DynamicRule::Confluent);

} // namespace trimlab
