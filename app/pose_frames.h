#pragma once
/// \file
/// `trimlab render ANIMATION --pose N | --poses A:B`: which poses of a mesh animation to
/// render, and each pose's output file (the pose number written into the name the way
/// printf writes it: frame_%04d.png -> frame_0007.png).

#include <QString>

#include <optional>

namespace trimlab::app {

struct PoseSelection {
    int first = 0;
    int last = 0;          ///< inclusive
    bool sequence = false; ///< --poses (one image per pose) rather than --pose
};

/// Parses --pose N (`pose`) or --poses A:B (`poses`, A <= B); at most one may be given
/// (empty text: not given). Leaves `out` empty when neither is; returns the one-line
/// error otherwise.
[[nodiscard]] std::optional<QString> parsePoseSelection(const QString& pose, const QString& poses,
                                                        std::optional<PoseSelection>& out);

/// Whether `pattern` holds exactly one pose number: %d, or %0Nd (zero-padded to N of 1
/// to 9 digits); "%%" stands for a literal %.
[[nodiscard]] bool hasPoseNumber(const QString& pattern);

/// `pattern` with its pose number written as `pose`; "%%" becomes "%". A pattern
/// without a pose number comes back as it is.
[[nodiscard]] QString posePath(const QString& pattern, int pose);

} // namespace trimlab::app
