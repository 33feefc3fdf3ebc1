#pragma once
/// \file
/// `trimlab trim SOURCE... --rule R [--csg EXPR] -o out.obj|.ply|.stl|.gltf|.glb`: the
/// trimmed solid the viewport shows, exported as exact geometry (core/solid).

#include <QStringList>

namespace trimlab::app {

int runTrimVerb(int argc, char** argv, const QStringList& arguments);

} // namespace trimlab::app
