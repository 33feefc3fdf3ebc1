# A probe for `scripts/gpu-check --probe scripts/gpu-probes/round-two.sh` (sourced there):
# what the full check does not measure of docs/gpu-results.md's round two, in one call —
# OpenCSG beside TrimLab (opencsg.sh), trimmed playback of samba (trimmed-playback.sh), the
# flaky rows over 20 cold processes (cold-processes.sh) and the wide-vector mend's timings
# (gpu-timings.sh). Each probe call has its own 120 s limit; the check's budget bounds the
# whole.
for part in opencsg trimmed-playback cold-processes gpu-timings; do
  # shellcheck source=/dev/null
  source "$root/scripts/gpu-probes/$part.sh"
done
