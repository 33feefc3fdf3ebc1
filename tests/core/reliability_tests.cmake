# Reliability (docs/reliability.md): the fuzz regression corpus and the broken-document
# table, and atomic saves under SIGKILL.
trimlab_add_test(core fuzz_regressions LIBS trimlab::core)
trimlab_add_test(core stale_temporaries LIBS trimlab::core)
add_executable(save_kill_helper save_kill_helper.cpp)
target_link_libraries(save_kill_helper PRIVATE trimlab::core)
set_target_properties(save_kill_helper PROPERTIES AUTOMOC OFF)
trimlab_set_warnings(save_kill_helper)
trimlab_add_test(core save_kill LIBS trimlab::core TIMEOUT 120)
target_compile_definitions(tst_core_save_kill PRIVATE SAVE_KILL_HELPER="$<TARGET_FILE:save_kill_helper>")
add_dependencies(tst_core_save_kill save_kill_helper)

# `trimlab info` on every broken mesh and NURBS file (the batch verbs' load path; label app).
if(TARGET trimlab)
  add_test(NAME app.info_broken_meshes
           COMMAND ${CMAKE_COMMAND} -DTRIMLAB=$<TARGET_FILE:trimlab> -DDATA=${TRIMLAB_TEST_DATA_DIR}
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/info_on_broken_meshes.cmake)
  set_tests_properties(app.info_broken_meshes PROPERTIES LABELS app TIMEOUT 300
                       ENVIRONMENT "QT_QPA_PLATFORM=offscreen")
endif()
