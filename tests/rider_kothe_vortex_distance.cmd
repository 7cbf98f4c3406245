# Issue 47: the Rider-Kothe vortex from a signed distance with the default
# transport, with the volume correction (tests/rider_kothe_vortex_distance.prm)
# and without it (the raw volume change).
set -eu
sed -e 's/Output directory = output/Output directory = uncorrected/' \
    rider_kothe_vortex_distance.prm > uncorrected.prm
printf 'subsection Transport\n  set Volume correction = false\nend\n' \
    >> uncorrected.prm
for scene in rider_kothe_vortex_distance uncorrected; do
  ${MPIRUN:-} "$VEFS" $scene.prm > $scene.screen
done
/usr/bin/python3 "$TEST_SOURCE_DIR/rider_kothe_vortex_distance.py" \
    output uncorrected
