# A probe for `scripts/gpu-check --probe scripts/gpu-probes/trimmed-playback.sh` (sourced
# there): trimmed animation playback at 1920x1080 — samba's 50 poses the bundle carries,
# skinned poses read as meshes, trimmed under a static rule and under a dynamic rule (each
# pose against the previous one), with the k⁺-buffer and the fixed A-buffer; `render`
# prints each pose's time, for the thesis's claim of playback rates (docs/gpu-results.md).
mkdir -p /tmp/trimlab-playback
for method in kplus-array abuffer-fixed; do
  probe ../bin/trimlab render "$TRIMLAB_SHARED_DATA_DIR/anim/samba" --poses 0:49 --rule alternating-border \
    --size 1920x1080 --repeat 3 --method "$method" -o "/tmp/trimlab-playback/static_%04d.png"
  probe ../bin/trimlab render "$TRIMLAB_SHARED_DATA_DIR/anim/samba" --poses 0:49 --dynamic-rule confluent \
    --reference previous --size 1920x1080 --repeat 3 --method "$method" -o "/tmp/trimlab-playback/dynamic_%04d.png"
done
