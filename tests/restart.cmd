# Checkpoint and restart. The scene restart.prm (or RESTART_PRM, if set)
# runs once without a stop;
# again with 'Checkpoint/Stop after steps = 12', so that it stops at steps
# 12 and 24 and is resumed twice with `vefs --resume`; and again stopped by
# SIGTERM part-way (exit status 128 + 15) and resumed. The resumed runs
# must end like the uninterrupted one: every statistics column within 1e-6
# of its largest value (wall_time and linear_iterations excepted) and the
# same visualization series. The resumed parts run with RESUME_MPIRUN if it
# is set (restart_fewer_ranks.cmd: 2 ranks, then 1), else with MPIRUN; the
# uninterrupted run with WHOLE_MPIRUN if it is set, else with MPIRUN.
set -u
source_prm=${TEST_SOURCE_DIR}/${RESTART_PRM:-restart.prm}
resume_launcher=${RESUME_MPIRUN-${MPIRUN:-}}
scene() { # output directory, steps before the stop
  sed -e "s|^set Output directory.*|set Output directory = $1|" \
      -e "s|set Stop after steps = 0|set Stop after steps = $2|" \
      "$source_prm" > "$1.prm"
}
# "stopped ... step 12 (t = 0.012) ...": the step and the exit status.
show() { # log, status
  echo "  $(grep -o '^vefs: stopped[^(]*[^( ]' "$1" || echo 'vefs: ran to the end')," \
       "exit status $2"
}

scene whole 0
status=0
${WHOLE_MPIRUN-${MPIRUN:-}} "$VEFS" whole.prm > whole.log 2>&1 || status=$?
echo "uninterrupted run: exit status $status"

echo "stopped by 'Stop after steps = 12', resumed twice:"
scene parts 12
status=0
${MPIRUN:-} "$VEFS" parts.prm > part1.log 2>&1 || status=$?
show part1.log $status
echo "  checkpoint files: $(ls parts/checkpoint | tr '\n' ' ')"
for part in 2 3; do
  status=0
  $resume_launcher "$VEFS" --resume parts > part$part.log 2>&1 || status=$?
  show part$part.log $status
done
/usr/bin/python3 "$TEST_SOURCE_DIR/restart_compare.py" whole parts

echo "stopped by SIGTERM, resumed:"
scene signal 0
${MPIRUN:-} "$VEFS" signal.prm > signal1.log 2>&1 &
launcher=$!
# Once a few steps are done, signal the vefs processes (mpirun's children).
for i in $(seq 600); do
  rows=$(grep -vc '^#' signal/statistics 2> /dev/null)
  [ "${rows:-0}" -ge 4 ] && break
  sleep 0.1
done
if [ -n "${MPIRUN:-}" ]; then pkill -TERM -P $launcher; else kill -TERM $launcher; fi
status=0
wait $launcher || status=$?
echo "  $(grep -o '^vefs: stopped by SIGTERM after step' signal1.log) #," \
     "exit status $status"
status=0
$resume_launcher "$VEFS" --resume signal > signal2.log 2>&1 || status=$?
show signal2.log $status
/usr/bin/python3 "$TEST_SOURCE_DIR/restart_compare.py" whole signal
