# A parameter file that does not exist: one message naming it, exit status 1.
set -u
status=0
"$VEFS" no_such_scene.prm 2> stderr.txt > /dev/null || status=$?
cat stderr.txt
echo "exit status: $status"
