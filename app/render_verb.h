#pragma once
/// \file
/// `trimlab render`: one image of a file or demo, through a multi-fragment method on OpenGL
/// (--method, default the k⁺-buffer) or the exact CPU reference, plus optional depth and
/// id files. Shares the scene loading, camera fitting and renderer with the GUI.

#include <QStringList>

namespace trimlab::app {

/// Runs the verb on the arguments after "render"; returns the process exit code
/// (0 success, 1 failed load/render/write, 2 bad arguments). Creates the Qt application
/// object it needs itself (a GUI one only for the OpenGL backend).
int runRenderVerb(int argc, char** argv, const QStringList& arguments);

} // namespace trimlab::app
