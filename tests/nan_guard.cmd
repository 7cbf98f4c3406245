# Runs that blow up stop with one message naming the step, the quantity and
# the entries to change, exit status 1, and leave statistics without
# non-finite numbers and the last good state for a look. The numbers in the
# messages are replaced by '#' (they depend on the machine and rank count).
set -u
run() {
  local name=$1
  shift
  {
    echo "set Output directory = $name"
    echo "subsection Mesh refinement"
    echo "  set Minimum level = 1"
    echo "  set Bulk level = 3"
    echo "  set Maximum level = 4"
    echo "end"
    echo "subsection Output"
    echo "  set Verbose = false"
    echo "end"
    printf '%s\n' "$@"
  } > "$name.prm"
  status=0
  ${MPIRUN:-} "$VEFS" "$name.prm" 2> stderr.txt > /dev/null || status=$?
  echo "$name:"
  grep '^vefs:' stderr.txt | sed -E 's/[0-9]+(\.[0-9]+)?(e[-+][0-9]+)?/#/g'
  echo "exit status: $status"
  echo "non-finite numbers in statistics: $(grep -v '^#' "$name/statistics" | grep -ciE 'nan|inf')"
  echo "visualization files: $(ls "$name" | grep -c 'pvtu$')"
}
# 1000 m/s: the first step would cross hundreds of cells.
run fast_start "subsection Initial liquid" "set Velocity = 1000; 0" "end"
# The velocity grows past the bound of the CFL number after a few steps.
run huge_gravity "set Gravity = 0, -1e5"
# A gravity so large that the Stokes solution overflows in a step (the
# second-order scheme's first solve fails so: solver_not_converging).
run overflowing_gravity "set Gravity = 0, -1e305" \
  "subsection Time" "set Scheme = first order" "end"
# Volume lost without correction, beyond a tight bound.
run volume_loss "subsection Transport" "set Volume correction = false" "end" \
  "subsection Health check" "set Maximum volume change = 1e-4" "end"
# With a target CFL, the steps that would be needed exceed the bound.
run too_many_steps "subsection Time" "set Time step = 0.1" "set Target CFL = 0.5" \
  "set Maximum steps = 20" "end"
# Steps that shrink without end (here forced by a tiny strain bound on a
# liquid with a stress) stop the run instead of crawling on.
run collapsing_step "subsection Material" "set Solvent viscosity = 1" \
  "set Polymer viscosity = 9" "set Relaxation time = 0.05" "end" \
  "subsection Time" "set Maximum strain per step = 1e-12" "end"
