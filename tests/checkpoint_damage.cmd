# Byte flips in every file of the newest checkpoint, one at a time: the
# state file (one flip in each line: the flips leave valid numbers, e.g.
# the step 2 becomes 3), the mesh files of p4est, the fields and
# parameters.prm (first, middle and last byte). Each damaged checkpoint/ is
# passed over with one warning naming the file, and the run resumes from
# checkpoint.old/ (the one before, kept for this); without checkpoint.old/,
# or with both damaged, --resume stops with one message and exit status 1.
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
status=0
${MPIRUN:-} "$VEFS" scene.prm > run.log 2>&1 || status=$?
echo "run stopped after 2 steps: exit status $status," \
     "checkpoints: $(cd output && ls -d checkpoint* | tr '\n' ' ')"
mv output pristine

flip() { # file, byte offset: XOR 1 (a digit stays a digit)
  /usr/bin/python3 - "$1" "$2" <<'PY'
import sys
path, offset = sys.argv[1], int(sys.argv[2])
with open(path, "r+b") as f:
    f.seek(offset)
    byte = f.read(1)
    f.seek(offset)
    f.write(bytes([byte[0] ^ 1]))
PY
}
resume() { # label
  status=0
  ${MPIRUN:-} "$VEFS" --resume output > out.txt 2> err.txt || status=$?
  # Resumed from step 2 the run ends at step 4; from step 1 (checkpoint.old)
  # it stops after its 2 steps, at step 3.
  echo "$1: exit status $status, statistics end with step" \
       "$(grep -v '^#' output/statistics | tail -n 1 | cut -d' ' -f1)"
  grep '^vefs:' err.txt | sed 's/^/  /'
}
fresh() {
  rm -rf output
  cp -r pristine output
}

fresh
resume "intact"
echo "  then: $(cd output && ls -d checkpoint* | tr '\n' ' ')"

# The state file: the last character of each line (for the 'file' lines
# the last digit of the checksum; for the last line that of the state's own
# checksum), and the first digit of the step and time.
lines=$(wc -l < pristine/checkpoint/state)
for line in $(seq 1 "$lines"); do
  fresh
  key=$(sed -n "${line}p" output/checkpoint/state | cut -d' ' -f1-2)
  [ "${key%% *}" = file ] || key=${key%% *}
  offset=$(head -n "$line" output/checkpoint/state | wc -c)
  flip output/checkpoint/state $((offset - 2))
  resume "state, line '$key'"
  [ "$line" = 1 ] &&
    echo "  then: $(cd output && ls -d checkpoint* | tr '\n' ' ')"
done
for key in step time; do
  fresh
  offset=$(grep -b "^$key " output/checkpoint/state | cut -d: -f1)
  flip output/checkpoint/state $((offset + ${#key} + 1))
  resume "state, first character of the $key"
done

for file in $(ls pristine/checkpoint | grep -v '^state$'); do
  size=$(wc -c < "pristine/checkpoint/$file")
  for where in first middle last; do
    case $where in
      first) offset=0 ;;
      middle) offset=$((size / 2)) ;;
      last) offset=$((size - 1)) ;;
    esac
    fresh
    flip "output/checkpoint/$file" $offset
    resume "$file, $where byte"
  done
done

echo "without checkpoint.old/:"
for file in state mesh parameters.prm; do
  fresh
  rm -r output/checkpoint.old
  size=$(wc -c < "output/checkpoint/$file")
  flip "output/checkpoint/$file" $((size / 2))
  resume "$file, middle byte"
done
echo "both damaged:"
fresh
flip output/checkpoint/mesh 100
flip output/checkpoint.old/state 100
resume "mesh of checkpoint/, state of checkpoint.old/"
echo "lock left: $(ls output/vefs.lock 2> /dev/null | wc -l)"
