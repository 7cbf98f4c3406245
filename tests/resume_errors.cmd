# `vefs --resume` refuses, with one message and exit status 1, a directory
# without a checkpoint, a parameter file beside the option, a directory in
# use (its lock file exists), a damaged checkpoint file and an incomplete
# state file (without checkpoint.old/ to fall back to); it takes over the lock of a killed run; a new run into the
# directory removes the old checkpoint.
set -u
cat > scene.prm <<'PRM'
set Output directory = output
subsection Time
  set End time = 0.004
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
attempt() { # label, arguments of vefs
  local label=$1
  shift
  status=0
  ${MPIRUN:-} "$VEFS" "$@" 2> stderr.txt > /dev/null || status=$?
  echo "$label: exit status $status"
  grep '^vefs:' stderr.txt
}
status=0
${MPIRUN:-} "$VEFS" scene.prm > run.log 2>&1 || status=$?
echo "run stopped after 2 steps: exit status $status"
cp -r output/checkpoint good_checkpoint

attempt "no such directory" --resume nowhere
mkdir empty
attempt "no checkpoint" --resume empty
attempt "parameter file too" --resume output scene.prm
touch output/vefs.lock
attempt "directory in use" --resume output
rm output/vefs.lock

# A damaged checkpoint without the one before (checkpoint.old/; with it,
# see checkpoint_damage.cmd) is refused.
rm -r output/checkpoint.old
/usr/bin/python3 - <<'PY'
with open("output/checkpoint/mesh", "r+b") as f:
    f.seek(100)
    byte = f.read(1)
    f.seek(100)
    f.write(bytes([byte[0] ^ 0xFF]))
PY
attempt "damaged mesh file" --resume output
rm -r output/checkpoint && cp -r good_checkpoint output/checkpoint
grep -v '^end$' good_checkpoint/state > output/checkpoint/state
attempt "incomplete state file" --resume output
rm -r output/checkpoint && cp -r good_checkpoint output/checkpoint
# The lock of a process that ended (kill -9) is taken over.
echo "$(sh -c 'echo $$') $(hostname)" > output/vefs.lock
attempt "lock of a killed run" --resume output

sed -e 's/Interval steps   = 1/Interval steps   = 0/' \
    -e 's/Stop after steps = 2/Stop after steps = 0/' scene.prm > fresh.prm
status=0
${MPIRUN:-} "$VEFS" fresh.prm > run.log 2>&1 || status=$?
echo "new run without checkpoints: exit status $status," \
     "checkpoint directories left: $(ls -d output/checkpoint* 2> /dev/null | wc -l)"
