# A probe for `scripts/gpu-check --probe scripts/gpu-probes/gpu-skinning.sh` (sourced there):
# GPU skinning on a real GPU. The test reads the skinned poses back against the CPU's
# (render.gpu_skinning; it skips without the samba poses, which scripts/gpu-bundle
# carries), then the bench times a pose both ways in one run: on llvmpipe the GPU path is
# slower than CPU skinning plus upload (docs/skinning.md), on a GPU it should be faster.
probe tst_render_gpu_skinning
probe ../bin/trimlab bench --scenes skinning:samba --repeat 3 --data "$TRIMLAB_SHARED_DATA_DIR"
