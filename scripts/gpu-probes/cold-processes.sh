# A probe for `scripts/gpu-check --probe scripts/gpu-probes/cold-processes.sh` (sourced
# there): the render.buffer_methods rows that failed now and then in the first process of a
# run on an NVIDIA H200 (docs/gpu-results.md, the open entry), in 20 cold processes — the
# driver's shader disk cache off, so that every process compiles its shaders as the first
# one of a run did. The test: the rows explained and fixed, or shown not to recur
# over 20 cold processes.
export __GL_SHADER_DISK_CACHE=0
for run in $(seq 1 20); do
  probe tst_render_buffer_methods countedMethodsMatchTheReferenceWithoutSilhouettes \
    listsLongerThanTheRegisterArrayStayExact listsBeyondTheLoopBudgetAreUnresolved
done
unset __GL_SHADER_DISK_CACHE
