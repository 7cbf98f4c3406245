# A probe point in empty space (above the broken dam's liquid): the run
# says so once on stderr; the columns probe_u_* hold the velocity field
# there (README, "Postprocess"), finite.
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
subsection Postprocess
  set Probe point = 0.2, 0.12
end
subsection Output
  set Verbose  = false
end
PRM
status=0
${MPIRUN:-} "$VEFS" scene.prm 2> stderr.txt > /dev/null || status=$?
grep '^vefs:' stderr.txt
echo "exit status $status"
/usr/bin/python3 - <<'PY'
import math
rows = [l.split() for l in open("output/statistics") if not l.startswith("#")]
header = [l for l in open("output/statistics") if l.startswith("# step")][0].split()[1:]
columns = [header.index(name) for name in header if name.startswith("probe_u_")]
values = [float(row[c]) for row in rows for c in columns]
print("probe columns: %d, rows: %d, all finite: %s"
      % (len(columns), len(rows), all(math.isfinite(v) for v in values)))
PY
