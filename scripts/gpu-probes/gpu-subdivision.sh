# A probe for `scripts/gpu-check --probe scripts/gpu-probes/gpu-subdivision.sh` (sourced
# there): subdivision surfaces evaluated on a real GPU by OpenSubdiv's GLSL compute
# evaluator. The test reads positions and normals back against the CPU's stencils and
# trims a GPU-evaluated edit against the reference (render.gpu_subdivision); the bench
# times one control-point edit of a 131,072-vertex limit surface both ways in one run: on
# llvmpipe the GPU path is slower than CPU stencils plus upload (docs/designer-workflow.md),
# on a GPU it should be faster. OpenSubdiv loads its GL functions
# from libGL.so.1 (the bundle carries glvnd's), so this also checks that its loader reaches
# the NVIDIA driver.
probe tst_render_gpu_subdivision
probe bench_gpu_subdivision 5 41
probe bench_gpu_subdivision 6 21
