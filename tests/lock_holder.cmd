# A refused lock says whose it is: the process and host the lock file
# names (a lock of another host is never taken over).
set -u
cat > scene.prm <<'PRM'
set Output directory = output
subsection Time
  set End time = 0.002
end
subsection Mesh refinement
  set Minimum level = 1
  set Bulk level    = 2
  set Maximum level = 3
end
subsection Output
  set Verbose  = false
end
PRM
mkdir -p output
echo "4242 another-host" > output/vefs.lock
status=0
${MPIRUN:-} "$VEFS" scene.prm 2> stderr.txt > /dev/null || status=$?
grep '^vefs:' stderr.txt
echo "locked by another host: exit status $status, lock kept: $(cat output/vefs.lock)"
