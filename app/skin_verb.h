#pragma once
/// \file
/// `trimlab skin ANIMATION --bones B [--method rigid|lbs|dqs] [options] -o out.glb`: approximates a
/// mesh animation by skinning (thesis chapter 4: B proxy bones from a segmentation into
/// exactly B segments, a pose-to-pose or classical LBS/DQS fit, optional vertex and weight
/// corrections) and exports it as glTF 2.0 (a skin with rigid joint animation, or morph
/// targets). ANIMATION is anything `trimlab segment` reads. See docs/skinning.md.

#include <QStringList>

namespace trimlab::app {

/// Runs the verb on the arguments after "skin"; returns the exit code (0 success, 1
/// unreadable or unsuitable input, 2 bad arguments). Prints on stdout the sizes, the
/// segmentation, the fit's E_RMS and the exported file's E_RMS (also over the rest-pose
/// bounding-box diagonal) and per-stage times (load, segmentation, weights, fit,
/// corrections, error, export); progress goes to stderr when it is a terminal.
int runSkinVerb(int argc, char** argv, const QStringList& arguments);

} // namespace trimlab::app
