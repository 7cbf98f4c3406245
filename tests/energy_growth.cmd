# Issue 51, point 2: a solid far too stiff for its time step must not end
# with exit 0 and energy it created. The stiff ball of
# bouncing_ball_2d_stiff with G = 1.2e9 Pa (Polymer viscosity 6.1e6 Pa s)
# on finest cells of 6.25 mm: its elastic wave crosses about 350 cells per
# step. No equation creates energy, so the health check must stop the run
# at the step whose total energy grows by more than 'Health check/Maximum
# energy growth' (0.01 of the energy above the lowest state), naming the
# elastic wave number (and warns once that it is beyond the trusted 10);
# exit status 1, no non-finite number in the
# statistics. Reference: energy conservation of the exact solution. The
# numbers in the message are replaced by '#' (machine and rank count).
set -u
sed -e 's/set Polymer viscosity = 10/set Polymer viscosity = 6.1e6/' \
    -e 's/set Maximum level = 5/set Maximum level = 4/' \
    -e 's/set Bulk level    = 4/set Bulk level    = 3/' \
    -e 's/set End time  = 0.36/set End time  = 0.3/' \
    "$TEST_SOURCE_DIR/bouncing_ball_2d_stiff.prm" > stiff.prm
for entry in "Polymer viscosity = 6.1e6" "Maximum level = 4" "End time  = 0.3"; do
  grep -q "set $entry" stiff.prm || echo "the scene was not edited: $entry"
done
status=0
${MPIRUN:-} "$VEFS" stiff.prm 2> stderr.txt > /dev/null || status=$?
grep '^vefs:' stderr.txt | sed -E 's/[0-9]+(\.[0-9]+)?(e[-+][0-9]+)?/#/g'
echo "exit status: $status"
echo "non-finite numbers in statistics: $(grep -v '^#' output/statistics | grep -ciE 'nan|inf')"
