# restart.cmd on restart_grandparents.prm (restart_contact.prm with the
# flow on the grandparents of the finest cells, 'Flow/Flow cells =
# grandparents'), its resumed parts on 3 ranks where the checkpoints were
# written on 2: every flow element's cells must be on one rank after the
# load on another number of ranks (mend_split_subtrees(); FlowElements
# stops otherwise), and the resumed runs must end like the uninterrupted
# one on 3 ranks (every statistics column within 1e-6 of its largest value;
# on 2 ranks the mesh has 3 cells more at one step than on 3).
export RESTART_PRM=restart_grandparents.prm
export RESUME_MPIRUN="${MPIRUN/-np 2/-np 3}"
export WHOLE_MPIRUN="$RESUME_MPIRUN"
source "$TEST_SOURCE_DIR/restart.cmd"
