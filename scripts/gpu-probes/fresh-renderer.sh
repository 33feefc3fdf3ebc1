# A probe for `scripts/gpu-check --probe scripts/gpu-probes/fresh-renderer.sh` (sourced there):
# the render.buffer_methods rows that fail now and then on an NVIDIA H200
# (docs/gpu-results.md, the open entry): each builds a new TrimRenderer for its row. The first process
# compiles the shaders cold; the later ones show whether a warm start passes.
probe tst_render_buffer_methods countedMethodsMatchTheReferenceWithoutSilhouettes \
  listsLongerThanTheRegisterArrayStayExact listsBeyondTheLoopBudgetAreUnresolved
probe tst_render_buffer_methods countedMethodsMatchTheReferenceWithoutSilhouettes \
  listsLongerThanTheRegisterArrayStayExact listsBeyondTheLoopBudgetAreUnresolved
probe tst_render_buffer_methods
