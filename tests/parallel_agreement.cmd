# The broken dam (short, coarse) on 1 and 2 MPI ranks must give the same
# statistics to 6 significant digits (numdiff -r 1e-6), except the columns
# that depend on the machine and the partition (wall time, iterations).
set -eu
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
sed 's|^set Output directory.*|set Output directory = serial|' parallel_agreement.prm > serial.prm
sed 's|^set Output directory.*|set Output directory = parallel|' parallel_agreement.prm > parallel.prm
"$VEFS" serial.prm > serial.log
mpirun -np 2 --oversubscribe "$VEFS" parallel.prm > parallel.log
strip() { awk '!/^#/{ $NF = ""; $(NF-1) = ""; print }' "$1"; }
strip serial/statistics > serial.txt
strip parallel/statistics > parallel.txt
echo "rows: $(wc -l < serial.txt) (serial) $(wc -l < parallel.txt) (2 ranks)"
if numdiff -q -r 1e-6 -a 1e-12 serial.txt parallel.txt > /dev/null; then
  echo "statistics agree to 6 significant digits: yes"
else
  numdiff -r 1e-6 -a 1e-12 serial.txt parallel.txt | tail -20 >&2
  echo "statistics agree to 6 significant digits: NO"
fi
