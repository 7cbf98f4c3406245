# A Stokes solve that does not converge stops the run: one message naming
# the entries to change, exit status 1. The numbers in the message are
# replaced by '#', so that the output does not depend on the machine.
# Twice: in a step (the first-order scheme), and in the second-order
# scheme's first solve, the initial acceleration.
set -u
for scheme in "first order" "second order"; do
  {
    cat solver_not_converging.prm
    printf 'subsection Time\n  set Scheme = %s\nend\n' "$scheme"
  } > run.prm
  rm -rf output
  status=0
  ${MPIRUN:-} "$VEFS" run.prm 2> stderr.txt > /dev/null || status=$?
  echo "$scheme:"
  grep '^vefs:' stderr.txt | sed -E 's/[0-9]+(\.[0-9]+)?(e[-+][0-9]+)?/#/g'
  echo "exit status: $status"
done
