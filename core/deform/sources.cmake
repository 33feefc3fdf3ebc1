# deform/: the designer's space-warp brush (thesis 8.2): strokes, local geodesics,
# falloff and angle attenuation, region smoothing and incremental normals.
target_sources(trimlab_core PRIVATE
  deform/stroke.cpp
  deform/brush_settings_check.cpp
  deform/brush_topology.cpp
  deform/closest_surface_point.cpp
  deform/local_geodesics.cpp
  deform/falloff.cpp
  deform/angle_attenuation.cpp
  deform/region_patch.cpp
  deform/region_smoothing.cpp
  deform/region_normals.cpp
  deform/brush_stroke.cpp
)
