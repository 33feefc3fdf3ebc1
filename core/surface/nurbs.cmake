# NURBS surfaces (core/surface/nurbs_*; thesis 8.2): exact rational evaluation, primitives,
# watertight fixed-connectivity tessellation with sparse re-evaluation, and the JSON
# format (docs/nurbs-json.md). mesh/obj_writer.h exports their tessellations.
target_sources(trimlab_core PRIVATE
  surface/nurbs_basis.cpp
  surface/nurbs_json.cpp
  surface/nurbs_primitives.cpp
  surface/nurbs_sampling.cpp
  surface/nurbs_surface.cpp
  surface/nurbs_tessellation.cpp
  surface/nurbs_tessellation_update.cpp
)
