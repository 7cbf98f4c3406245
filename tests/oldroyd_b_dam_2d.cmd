# Free-surface Oldroyd-B flow: the broken dam of oldroyd_b_dam_2d.prm
# (lambda = 0.05 s) beside the Newtonian liquid of the same total viscosity
# and the Oldroyd-B liquid with lambda = 1e-4 s. Reference: as lambda -> 0
# the Oldroyd-B liquid is the Newtonian liquid of viscosity eta_s + eta_p
# (seed, section 3), so the lambda = 1e-4 s front must match the Newtonian
# front (tolerance 1%: lambda / tau = 0.1 and lambda times the shear rate
# are the size of the remaining polymer memory). The checker prints fronts
# and energies with 3 significant digits.
set -eu
sed -e 's/Relaxation time   = 0.05/Relaxation time   = 0/' \
    -e 's/Output directory = output/Output directory = newtonian/' \
    oldroyd_b_dam_2d.prm > newtonian.prm
sed -e 's/Relaxation time   = 0.05/Relaxation time   = 0.0001/' \
    -e 's/Output directory = output/Output directory = small_lambda/' \
    oldroyd_b_dam_2d.prm > small_lambda.prm
for scene in oldroyd_b_dam_2d newtonian small_lambda; do
  ${MPIRUN:-} "$VEFS" $scene.prm > $scene.screen
done
/usr/bin/python3 "$TEST_SOURCE_DIR/oldroyd_b_dam_2d.py" output newtonian small_lambda
