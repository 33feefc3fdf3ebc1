# Surfaces designers edit through control points (thesis 8.2): NURBS (nurbs.cmake) and
# OpenSubdiv subdivision surfaces (subdivision.cmake), each tessellated into a trimmable
# triangle mesh whose connectivity stays fixed while control points move.
include(${CMAKE_CURRENT_LIST_DIR}/nurbs.cmake OPTIONAL)
include(${CMAKE_CURRENT_LIST_DIR}/subdivision.cmake OPTIONAL)
# Editable surfaces as documents (editing.cmake): definitions, the evaluator, control
# edits as timeline frames, the control-point brush, surface scenes and demo histories.
include(${CMAKE_CURRENT_LIST_DIR}/editing.cmake OPTIONAL)
