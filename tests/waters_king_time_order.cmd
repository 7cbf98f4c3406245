# Issue 49: Waters & King's start-up flow at tau = 0.04 and 0.02 on level 2
# with the second-order scheme and the default weight of the new forces
# (the trapezoidal rule's 1/2 without contact walls), and at tau = 0.0025
# as the reference of the time error;
# waters_king_time_order.py checks that the time error falls as tau^2.
set -eu
sed -e 's/Output directory = output/Output directory = half_step/' \
    -e 's/Time step *= 0.04$/Time step = 0.02/' \
    waters_king_time_order.prm > half_step.prm
grep -q '^ *set Time step = 0\.02$' half_step.prm # stops if sed missed
sed -e 's/Output directory = output/Output directory = reference/' \
    -e 's/Time step *= 0.04$/Time step = 0.0025/' \
    waters_king_time_order.prm > reference.prm
grep -q '^ *set Time step = 0\.0025$' reference.prm # stops if sed missed
for scene in waters_king_time_order half_step reference; do
  ${MPIRUN:-} "$VEFS" $scene.prm > $scene.screen
done
/usr/bin/python3 "$TEST_SOURCE_DIR/waters_king_time_order.py" \
  output half_step reference
