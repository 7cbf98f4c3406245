# Two SIGTERMs a few ms apart, as coreutils' `timeout` sends them (to the
# process, then to its process group): the second is the same request, so
# the run still ends with a checkpoint, exit status 143 and no lock left.
# A SIGTERM more than 2 s after the first ends the process at once.
set -u
cat > scene.prm <<'PRM'
set Output directory = output
subsection Time
  set End time = 10
end
subsection Mesh refinement
  set Minimum level = 1
  set Bulk level    = 2
  set Maximum level = 3
end
subsection Output
  set Interval = 0
  set Verbose  = false
end
PRM
signal_run() { # seconds between the two signals
  rm -rf output
  ${MPIRUN:-} "$VEFS" scene.prm > run.log 2>&1 &
  launcher=$!
  for i in $(seq 600); do
    rows=$(grep -vc '^#' output/statistics 2> /dev/null)
    [ "${rows:-0}" -ge 3 ] && break
    sleep 0.1
  done
  for i in 1 2; do
    if [ -n "${MPIRUN:-}" ]; then pkill -TERM -P $launcher; else kill -TERM $launcher; fi
    [ $i = 1 ] && sleep "$1"
  done
  status=0
  wait $launcher || status=$?
}

signal_run 0.005
echo "two SIGTERMs 5 ms apart:"
echo "  $(grep -o '^vefs: stopped by SIGTERM after step' run.log || echo 'no stop message'), exit status $status"
echo "  checkpoint written: $(ls output/checkpoint/state 2> /dev/null | wc -l), lock left: $(ls output/vefs.lock 2> /dev/null | wc -l)"
