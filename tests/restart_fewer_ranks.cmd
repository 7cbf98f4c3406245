# restart.cmd with the resumed parts on one rank: a checkpoint written on
# 2 ranks must continue on 1 (statistics within 1e-6, as restart.cmd).
export RESUME_MPIRUN=
source "$TEST_SOURCE_DIR/restart.cmd"
