# The hard case of Waters & King (prm/waters_king_hard.prm: E = 5,
# beta = 1/20) on level 2 at four times its step (tau = 0.2) for five steps,
# with the seed's linear stress update and with the exponential one.
# Reference: exp(tau L) c exp(tau L)^T is positive definite whenever c is,
# so the exponential run keeps every eigenvalue of c positive and says
# nothing; the linear update c + tau (L c + c L^T) does not at this step
# (doc/viscoelastic.md, "Positivity"): that run says so once on stderr,
# names the remedy and goes on. Counts and eigenvalues are masked (#).
set -eu
for update in linear exponential; do
  cat > $update.prm <<PRM
set Dimension        = 2
set Output directory = $update
set Gravity          = 3, 0
subsection Time
  set End time  = 1
  set Time step = 0.2
end
subsection Cavity
  set Lower corner        = 0, -1
  set Upper corner        = 0.25, 1
  set Coarse subdivisions = 1, 8
end
subsection Walls
  set x- = periodic
  set x+ = periodic
  set y- = no-slip
  set y+ = no-slip
end
subsection Material
  set Density           = 1
  set Solvent viscosity = 0.05
  set Polymer viscosity = 0.95
  set Relaxation time   = 5
  set Alpha             = 1
end
subsection Initial liquid
  set Shape            = box
  set Box lower corner = 0, -1
  set Box upper corner = 0.25, 1
end
subsection Mesh refinement
  set Minimum level = 2
  set Bulk level    = 2
  set Maximum level = 2
end
subsection Stress
  set Stress update = $update
end
subsection Output
  set Interval = 0
  set Verbose  = false
end
PRM
  status=0
  ${MPIRUN:-} "$VEFS" $update.prm 2> $update.stderr > /dev/null || status=$?
  echo "$update update: exit status $status, warnings $(grep -c '^vefs: warning' $update.stderr || true)"
  sed -E -e 's/at [0-9]+ quadrature/at # quadrature/' \
         -e 's/eigenvalue [-+0-9.e]+;/eigenvalue #;/' $update.stderr
  /usr/bin/python3 "$TEST_SOURCE_DIR/conformation_not_positive.py" $update
done
