#pragma once
/// \file
/// `trimlab segment ANIMATION --clusters N --h H [options] -o labels.json|labels.csv|seg.gltf`:
/// segments a mesh animation (thesis chapter 3: per-pose partitions, their
/// over-segmentation and p2p-cleaning) and writes the per-vertex labels. ANIMATION is a
/// folder of mesh files, a numbered pattern ("dir/mesh_%04d.obj.gz"), a wildcard pattern
/// ("dir/mesh_*.obj.gz") or a glTF file with a morph-target or skinned animation.

#include <QStringList>

namespace trimlab::app {

/// Runs the verb on the arguments after "segment"; returns the exit code (0 success,
/// 1 unreadable or unsuitable input, 2 bad arguments). Prints the segment counts and the
/// per-stage times (load, features, partitions, over-segmentation, cleaning) on stdout.
int runSegmentVerb(int argc, char** argv, const QStringList& arguments);

} // namespace trimlab::app
