# trim/: winding-index rules, the exact CPU reference ray caster and its diagnostics.
target_sources(trimlab_core PRIVATE
  trim/ray_triangle.cpp
  trim/triangle_bvh.cpp
  trim/clip_set.cpp
  trim/csg_expression.cpp
  trim/inspect_settings.cpp
  trim/trim_walk.cpp
  trim/transparency.cpp
  trim/reference_diagnostics.cpp
  trim/reference_renderer.cpp
  trim/trim_agreement.cpp
  trim/winding_number.cpp
  trim/dynamic_frame_scene.cpp
  trim/dynamic_walk.cpp
  trim/dynamic_chain.cpp
  trim/dynamic_reference_renderer.cpp
  trim/trim_membership.cpp
)
# The watertight ray-triangle test relies on every vertex being sheared by identical
# rounded operations in every triangle, and its exact-sign code on plain IEEE products
# and sums: no contraction into fused multiply-adds.
set_source_files_properties(trim/ray_triangle.cpp trim/triangle_bvh.cpp
  PROPERTIES COMPILE_OPTIONS -ffp-contract=off)
