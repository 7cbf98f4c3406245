# The output directory of a run: a second run into a directory in use (its
# lock file exists) is refused; a new run removes the results of an
# earlier one, so that the files of two runs never mix.
set -u
cat > scene.prm <<'PRM'
set Output directory = output
subsection Time
  set End time = 0.003
end
subsection Mesh refinement
  set Minimum level = 1
  set Bulk level    = 2
  set Maximum level = 3
end
subsection Output
  set Interval = 1
  set Verbose  = false
end
PRM
mkdir -p output
touch output/vefs.lock
status=0
${MPIRUN:-} "$VEFS" scene.prm 2> stderr.txt > /dev/null || status=$?
grep '^vefs:' stderr.txt
echo "locked: exit status $status"
rm output/vefs.lock
# Results of an earlier, longer run, and a file of the user.
touch output/solution_00099.vtu output/solution_00099.pvtu output/notes.txt
echo "# old" > output/statistics
status=0
${MPIRUN:-} "$VEFS" scene.prm 2> stderr.txt > /dev/null || status=$?
echo "second run: exit status $status"
ls output | grep -v '^solution_0000[0-3]' | sort
echo "visualization files: $(ls output | grep -c '^solution_0000[0-3]\.pvtu')"
echo "statistics rows: $(grep -vc '^#' output/statistics)"
