# A probe for `scripts/gpu-check --probe scripts/gpu-probes/subdivision-fallback.sh`:
# render.gpu_subdivision on an NVIDIA H200, where a viewport frame stored 0 fragments after
# earlier renderers of the same context had gone, positions right (docs/gpu-results.md).
# With the driver's debug messages (TRIMLAB_GL_DEBUG, render/gl/gl_debug_log.h): the whole
# binary three times, the shader library's current-program check, and the
# render.buffer_methods rows that fail now and then with a fresh renderer.
export TRIMLAB_GL_DEBUG=1
probe tst_render_gpu_subdivision
probe tst_render_gpu_subdivision
probe tst_render_gpu_subdivision
probe tst_render_shader_library noDeletedProgramStaysCurrent
probe tst_render_buffer_methods countedMethodsMatchTheReferenceWithoutSilhouettes \
  listsLongerThanTheRegisterArrayStayExact listsBeyondTheLoopBudgetAreUnresolved
unset TRIMLAB_GL_DEBUG
probe tst_render_gpu_subdivision
keep '*viewport*'
