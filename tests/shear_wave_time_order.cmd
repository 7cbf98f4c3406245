# Issue 49: the standing shear wave at tau = 0.02 and 0.01 on level 4 with
# the second-order scheme and the default weight of the new forces (the
# trapezoidal rule's 1/2 without contact walls);
# shear_wave_time_order.py checks that the amplitude loss falls as tau^2.
set -eu
sed -e 's/Output directory = output/Output directory = half_step/' \
    -e 's/Time step *= 0.02$/Time step = 0.01/' \
    shear_wave_time_order.prm > half_step.prm
grep -q '^ *set Time step = 0\.01$' half_step.prm # stops if sed missed
for scene in shear_wave_time_order half_step; do
  ${MPIRUN:-} "$VEFS" $scene.prm > $scene.screen
done
/usr/bin/python3 "$TEST_SOURCE_DIR/shear_wave_time_order.py" output half_step
