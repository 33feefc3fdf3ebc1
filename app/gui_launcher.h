#pragma once
/// \file
/// Starts the GUI: `trimlab [FILE|demo:NAME]`.

namespace trimlab::app {

/// Runs the main window's event loop; opens argv[1] when given (a file or demo:NAME),
/// otherwise the window shows its default demo. Returns the exit code.
int runGui(int argc, char** argv);

} // namespace trimlab::app
