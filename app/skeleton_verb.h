#pragma once
/// \file
/// `trimlab skeleton MESH [--nodes N] [--ordering amd|colamd|metis] [--solver cholmod|ldlt]
/// [--root J] [--loop-subdivide N] [-o rig.glb] [--json skeleton.json]`: extracts an
/// animation skeleton from a closed mesh by mesh contraction (Berenguer & Moreno III.A–D),
/// computes bone-heat skinning weights (III.E) and exports the rigged mesh as glTF and the
/// skeleton as JSON (III.F). MESH is any mesh file TrimLab reads or a demo:NAME with one
/// object. See docs/skeleton.md.

#include <QStringList>

namespace trimlab::app {

/// Runs the verb on the arguments after "skeleton"; returns the exit code (0 success, 1
/// unreadable or refused mesh — open, non-manifold, several components — or a failed
/// export, 2 bad arguments). Prints on stdout the mesh sizes, the rig, and one row with
/// the columns of the paper's Table III: vertices, contraction iterations and the times
/// of contraction, simplification, refinement, selection, weights, export and their total
/// in seconds; progress goes to stderr when it is a terminal.
int runSkeletonVerb(int argc, char** argv, const QStringList& arguments);

} // namespace trimlab::app
