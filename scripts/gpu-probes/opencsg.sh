# A probe for `scripts/gpu-check --probe scripts/gpu-probes/opencsg.sh` (sourced there):
# OpenCSG (OpenSCAD's preview, Goldfeather) timed beside TrimLab's buffer methods on the
# same CSG of three closed operands, the same views and the same GPU, every image against
# the exact CPU reference (tests/render/bench_opencsg.cpp). For docs/gpu-results.md's
# OpenCSG column: 1920x1080 and the 4K screen of the goal.
probe bench_opencsg --size 1920x1080 --views 2 --repeat 5
probe bench_opencsg --size 3840x2160 --views 1 --repeat 5
