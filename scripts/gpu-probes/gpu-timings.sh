# A probe for `scripts/gpu-check --probe scripts/gpu-probes/gpu-timings.sh`: the benches
# of gpu-skinning.sh and gpu-subdivision.sh without their tests (which the full check
# runs), for the first hardware timings of both GPU paths in one short call (the bundle carries
# the samba poses only).
probe ../bin/trimlab bench --scenes skinning:samba --repeat 3 --data "$TRIMLAB_SHARED_DATA_DIR"
probe bench_gpu_subdivision 5 41
probe bench_gpu_subdivision 4 41
