# restart.cmd on restart_contact.prm: stopped and resumed while the ball
# touches the floor; the resumed runs must end like the uninterrupted one
# (every statistics column within 1e-6 of its largest value, the contact
# force and length included).
export RESTART_PRM=restart_contact.prm
source "$TEST_SOURCE_DIR/restart.cmd"
