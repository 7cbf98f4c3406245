# A slip wall is a plane of symmetry: the half ball of slip_wall_symmetry.prm
# on its slip floor against the whole ball vibrating freely in a cavity twice
# as tall (the same cells, the floor line inside). Reference: mirror
# symmetry, so the two lose the same fraction of their energy and keep the
# same width. The checker prints both with 2-3 significant digits.
set -eu
sed -e 's/Lower corner        = -0.2, 0$/Lower corner        = -0.2, -0.2/' \
    -e 's/Coarse subdivisions = 4, 2/Coarse subdivisions = 4, 4/' \
    -e 's/Output directory = output/Output directory = free/' \
    slip_wall_symmetry.prm > free.prm
grep -q 'Lower corner        = -0.2, -0.2' free.prm
for scene in slip_wall_symmetry free; do
  ${MPIRUN:-} "$VEFS" $scene.prm > $scene.screen
done
/usr/bin/python3 "$TEST_SOURCE_DIR/slip_wall_symmetry.py" output free
