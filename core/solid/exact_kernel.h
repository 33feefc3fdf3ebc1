#pragma once
/// \file
/// The exact kernel of the trimmed-solid export (CGAL's exact predicates and exact
/// constructions): every point of the refined arrangement is an exact rational, so
/// orientation tests, the order of faces around an edge and ray crossings are decided
/// without rounding. Internal to core/solid; nothing outside includes CGAL.

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

namespace trimlab::solid {

using ExactKernel = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactPoint = ExactKernel::Point_3;
using ExactVector = ExactKernel::Vector_3;

} // namespace trimlab::solid
