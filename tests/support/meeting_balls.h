#pragma once
/// \file
/// A small mesh animation whose poses pass through each other, written as files for
/// tests that open animations the way a user does: two unit balls (icospheres, level 2)
/// that move towards each other over three poses (centres ±1.4, ±0.8, ±0.5 on x) until
/// they overlap in a lens. Under parity alone the lens (winding 2) is carved out; a
/// dynamic rule that remembers both balls were solid before they met keeps it, so a plane
/// through the centres tells the rules apart.

#include <QString>

namespace trimlab::test {

/// Writes pose_0.obj … pose_2.obj into `folder` (created if missing). Returns false when a
/// file cannot be written.
[[nodiscard]] bool writeMeetingBalls(const QString& folder);

} // namespace trimlab::test
