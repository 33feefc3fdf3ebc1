# Editable surfaces as documents (thesis 8.2): what a surface is before edits
# (surface_definition), its fixed-connectivity evaluator (editable_surface), control-point
# edits as timeline frames (control_edit), the control-point brush (control_brush), scene
# sources for surface files and demos (surface_scenes) and the Fig. 8.13 history.
target_sources(trimlab_core PRIVATE
  surface/surface_definition.cpp
  surface/editable_surface.cpp
  surface/control_edit.cpp
  surface/control_brush.cpp
  surface/surface_scenes.cpp
  surface/fig8_13_history.cpp
)
