#pragma once
/// \file
/// `trimlab bench`: every multi-fragment method of this build on a fixed camera path over
/// named scenes (bench_scenes.h) at chosen sizes, each frame checked against the exact CPU
/// reference. Prints a header and a table (bench_table.h), optionally JSON (bench_json.h).
/// Shares the scene loading, renderer and agreement criteria with the GUI and the tests.
/// A developer tool: its file scenes read the shared data folder, and a missing file only
/// skips that scene.

#include <QStringList>

namespace trimlab::app {

/// Runs the verb on the arguments after "bench"; returns the exit code: 0 when every
/// method agreed with the reference (speed never fails), 1 when one disagreed beyond the
/// render tests' threshold, could not render (other than running out of GPU memory) or a
/// scene could not be loaded, 2 for bad arguments.
int runBenchVerb(int argc, char** argv, const QStringList& arguments);

} // namespace trimlab::app
