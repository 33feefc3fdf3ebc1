# The editable-surface UI (thesis 8.2): Create menu, Surface panel, control net overlay,
# control-point tool and its undo command, the brush on control points.
target_sources(trimlab_ui PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/control_brush_drag.cpp
  ${CMAKE_CURRENT_LIST_DIR}/control_net_overlay.cpp
  ${CMAKE_CURRENT_LIST_DIR}/control_point_pick.cpp
  ${CMAKE_CURRENT_LIST_DIR}/control_point_tool.cpp
  ${CMAKE_CURRENT_LIST_DIR}/control_preview.cpp
  ${CMAKE_CURRENT_LIST_DIR}/main_window_surface.cpp
  ${CMAKE_CURRENT_LIST_DIR}/surface_definitions.cpp
  ${CMAKE_CURRENT_LIST_DIR}/surface_panel.cpp
  ${CMAKE_CURRENT_LIST_DIR}/surface_settings_store.cpp
)
