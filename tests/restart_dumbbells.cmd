# restart.cmd on restart_dumbbells.prm (the Oldroyd-B dam of restart.prm
# with its stress carried by 20 dumbbell fields, doc/dumbbells.md): the
# resumed runs must end like the uninterrupted one, every statistics column
# within 1e-6 of its largest value (the probe-free scene's energies,
# volume, front and conformation included).
export RESTART_PRM=restart_dumbbells.prm
source "$TEST_SOURCE_DIR/restart.cmd"
