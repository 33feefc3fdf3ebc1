#pragma once
/// \file
/// The name filter of File ▸ Open…, built from supportedMeshExtensions() (mesh_io.h) so
/// the dialog offers exactly what loadMesh accepts, gzip-compressed variants included.

#include <QString>

namespace trimlab::ui {

/// "Meshes (*.obj *.off … *.obj.gz …);;OBJ (*.obj *.obj.gz);;…;;All files (*)".
[[nodiscard]] QString meshFileDialogFilter();

} // namespace trimlab::ui
