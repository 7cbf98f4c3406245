# Inputs refused before any work, each with one message and exit status 1:
# a directory given as the parameter file, and mesh levels that need more
# memory than the machine has (the numbers of that message depend on the
# machine and are replaced by '#').
set -u
run() {
  status=0
  ${MPIRUN:-} "$VEFS" "$@" 2> stderr.txt > /dev/null || status=$?
  grep '^vefs:' stderr.txt | sed -E 's/[0-9]+(\.[0-9]+)?(e[-+][0-9]+)?/#/g'
  echo "exit status: $status"
}
mkdir -p scene_directory
run scene_directory
cat > huge_levels.prm <<'PRM'
subsection Mesh refinement
  set Maximum level = 20
end
PRM
run huge_levels.prm
