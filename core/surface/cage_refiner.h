#pragma once
/// \file
/// The OpenSubdiv view of a SubdivisionCage: a Far::TopologyRefiner holding its topology,
/// scheme, boundary rule and sharpness tags (not yet refined). Used by the surface builder
/// and by checks that evaluate the surface through OpenSubdiv directly. Including this
/// header requires OpenSubdiv's include path (link OpenSubdiv::osdCPU).

#include "core/surface/subdivision_cage.h"

#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/topologyRefiner.h>

#include <memory>

namespace trimlab {

/// A new, unrefined refiner for `cage` (which should have passed validateCage).
/// Sdc options: the cage's scheme and boundary interpolation, OpenSubdiv's defaults
/// otherwise (uniform crease method, Catmull–Clark triangle rule). Creases become
/// creaseVertexIndexPairs/creaseWeights, corners cornerVertexIndices/cornerWeights.
/// Throws SubdivisionError if OpenSubdiv refuses the topology.
[[nodiscard]] std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> createCageRefiner(const SubdivisionCage& cage);

/// The patch options behind SubdivisionSurface's limit mode: feature-adaptive isolation
/// to SubdivisionSurface::kLimitIsolationLevel, infinitely sharp patches for infinitely
/// sharp features (exact creases without isolating them to the last level), Gregory-basis
/// end caps, double-precision local points, no varying or face-varying tables. Refine with
/// `refiner.RefineAdaptive(limitPatchOptions().GetRefineAdaptiveOptions())`.
[[nodiscard]] OpenSubdiv::Far::PatchTableFactory::Options limitPatchOptions();

} // namespace trimlab
