#pragma once
/// \file
/// A loaded scene with the holes of its objects closed (core/trim/hole_closing.h), as
/// `--close-holes` and the window's Close Holes action give it: each open object closed by
/// fans, its validation report redone, so the trim modes become available where the
/// holes were the only defect.

#include "core/catalog/scene_source.h"
#include "core/trim/hole_closing.h"

namespace trimlab {

/// Closes the holes of every object of `loaded` in place and returns what was closed, with
/// the first fan that crosses its object's surface (named "object 'NAME': " in a scene of
/// several). Throws MeshLoadError naming the source and the object when a boundary does
/// not form loops; `loaded` is unchanged then.
HoleClosing closeSceneHoles(LoadedScene& loaded);

} // namespace trimlab
