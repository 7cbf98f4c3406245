# Writes that fail (doc/checkpoints.md, "Full disks"): a run whose files
# cannot be written stops on every rank with one message naming the file,
# the step and the cause, exit status 1, no lock and no partial checkpoint
# left, and the last checkpoint resumes. The disk is made full for chosen
# files by tests/write_fault (preloaded: their writes fail with ENOSPC).
# Each case runs 2 steps with checkpoints, resumes with the fault (2 more
# steps would follow), then resumes without it.
set -u
cat > scene.prm <<'PRM'
set Output directory = output
subsection Time
  set End time = 0.008
end
subsection Mesh refinement
  set Minimum level = 1
  set Bulk level    = 2
  set Maximum level = 3
end
subsection Checkpoint
  set Interval steps   = 1
  set Stop after steps = 2
end
subsection Output
  set Interval = 1
  set Verbose  = false
end
PRM
fault() { # the files that cannot be written (a part of their path), then
           # the arguments of vefs
  local file=$1
  shift
  status=0
  if [ -n "${MPIRUN:-}" ]; then
    VEFS_WRITE_FAULT="$file" LD_PRELOAD="$VEFS_WRITE_FAULT_LIBRARY" \
      $MPIRUN -x VEFS_WRITE_FAULT -x LD_PRELOAD "$VEFS" "$@" \
      > out.txt 2> err.txt || status=$?
  else
    VEFS_WRITE_FAULT="$file" LD_PRELOAD="$VEFS_WRITE_FAULT_LIBRARY" \
      "$VEFS" "$@" > out.txt 2> err.txt || status=$?
  fi
  echo "  no space for '$file': exit status $status"
  # vefs' messages, without Open MPI's.
  grep '^vefs:' err.txt | sed 's/^/    /'
  echo "    lock left: $(ls output/vefs.lock 2> /dev/null | wc -l)," \
       "checkpoints: $(cd output 2> /dev/null && ls -d checkpoint* 2> /dev/null | tr '\n' ' ')"
}
resume() {
  status=0
  ${MPIRUN:-} "$VEFS" --resume output > out.txt 2> err.txt || status=$?
  echo "    resumed without the fault: exit status $status, statistics end" \
       "with step $(grep -v '^#' output/statistics | tail -n 1 | cut -d' ' -f1)"
}

echo "fresh runs:"
for file in parameters.prm statistics solution_00000; do
  rm -rf output
  fault "$file" scene.prm
done
echo "resumed runs:"
for file in statistics solution_00003 solution.pvd checkpoint.new/mesh \
            checkpoint.new/state; do
  rm -rf output
  ${MPIRUN:-} "$VEFS" scene.prm > run.log 2>&1
  fault "$file" --resume output
  resume
done
