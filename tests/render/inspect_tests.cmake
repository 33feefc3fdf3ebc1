# Interior inspection on the GPU: clip sets, capping, CSG and highlights against the CPU
# reference, coplanar stability, and the independent OpenCSG comparison.
trimlab_add_test(render inspect_methods LIBS trimlab_gl_test_support)
trimlab_add_test(render coplanar_methods LIBS trimlab_gl_test_support)

# The independent check: OpenCSG (Debian libopencsg-dev, with GLEW: libglew-dev) renders
# the same CSG expressions in a compatibility context of its own.
find_path(OPENCSG_INCLUDE_DIR opencsg.h)
find_library(OPENCSG_LIBRARY opencsg)
find_package(GLEW QUIET)
find_package(OpenGL QUIET COMPONENTS OpenGL)
if(OPENCSG_INCLUDE_DIR AND OPENCSG_LIBRARY AND GLEW_FOUND AND TARGET OpenGL::GL)
  trimlab_add_test(render opencsg_comparison LIBS trimlab_gl_test_support ${OPENCSG_LIBRARY} GLEW::GLEW OpenGL::GL)
  target_sources(tst_render_opencsg_comparison PRIVATE opencsg_depth.cpp)
  target_include_directories(tst_render_opencsg_comparison PRIVATE ${OPENCSG_INCLUDE_DIR})
else()
  # Never a silent skip: the test exists and fails, naming what to install.
  message(WARNING "OpenCSG or GLEW not found: render.opencsg_comparison will fail (run scripts/install-deps)")
  add_test(NAME render.opencsg_comparison
           COMMAND sh -c "echo 'OpenCSG or GLEW missing: install libopencsg-dev libglew-dev'; exit 1")
  set_tests_properties(render.opencsg_comparison PROPERTIES LABELS render)
endif()

# Transparency / X-ray: every buffer method's colors against the CPU reference.
trimlab_add_test(render transparency_methods LIBS trimlab_gl_test_support)
