# A Stokes solve that does not converge stops the run: one message naming
# the entries to change, exit status 1. The numbers in the message are
# replaced by '#', so that the output does not depend on the machine.
set -u
status=0
${MPIRUN:-} "$VEFS" solver_not_converging.prm 2> stderr.txt > /dev/null || status=$?
grep '^vefs:' stderr.txt | sed -E 's/[0-9]+(\.[0-9]+)?(e[-+][0-9]+)?/#/g'
echo "exit status: $status"
