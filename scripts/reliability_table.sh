#!/usr/bin/env bash
# Usage: scripts/reliability_table.sh [WORKDIR]
# Runs vefs on a list of bad inputs (quick manual runs) and prints the
# markdown rows of doc/bad_inputs.md: input, exit status, message (first
# line of stderr, the run directory stripped). Works from any cwd.
set -u
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
VEFS="$ROOT/build/vefs"
WORK="${1:-$(mktemp -d)}"
mkdir -p "$WORK" && cd "$WORK" || exit 1
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
n=0
# case DESCRIPTION RANKS PRM-TEXT [ARGS]: runs vefs on case_N.prm (or ARGS).
case_() {
  local description=$1 ranks=$2 text=$3
  shift 3
  n=$((n + 1))
  rm -rf "out_$n"
  if [[ $text == RAW:* ]]; then
    printf '%s\n' "${text#RAW:}" > "case_$n.prm"
  else
    printf 'set Output directory = out_%s\nsubsection Time\n  set End time = 0.01\nend\nsubsection Output\n  set Interval = 0\n  set Verbose = false\nend\n%s\n' \
      "$n" "$text" > "case_$n.prm"
  fi
  local args=("case_$n.prm")
  (($#)) && args=("$@")
  local launcher=()
  ((ranks > 1)) && launcher=(mpirun -np "$ranks" --oversubscribe)
  local status=0
  "${launcher[@]}" "$VEFS" "${args[@]}" > /dev/null 2> err.txt || status=$?
  local message
  # All lines of the message in one, without Open MPI's own lines.
  message=$(awk '/^vefs:/ { keep = 1 } /^[^ ]/ && !/^vefs:/ { keep = 0 }
    keep' err.txt |
    tr -s ' \n' ' ' | sed 's/|/\\|/g')
  echo "| $n | $description | $ranks | $status | $message |"
}
sub() { printf 'subsection %s\n  set %s\nend\n' "$1" "$2"; }

case_ "initial velocity 1/0" 1 "$(sub 'Initial liquid' 'Velocity = 1/0; 0')"
case_ "initial velocity 1000 m/s" 1 "$(sub 'Initial liquid' 'Velocity = 1000; 0')"
case_ "initial velocity 1000 m/s" 2 "$(sub 'Initial liquid' 'Velocity = 1000; 0')"
case_ "wall velocity with a pole at t = 0.005" 1 "$(printf 'subsection Walls\n set y+ = velocity\n set y+ velocity = 1/(t-0.005); 0\nend')"
case_ "wall velocity with a pole off the wall (x = -1)" 1 "$(printf 'subsection Walls\n set x- = velocity\n set x- velocity = 0; 1/(x+1)\nend')"
case_ "gravity 0, -1e5" 1 "set Gravity = 0, -1e5"
case_ "gravity 0, -1e305 (overflow)" 1 "set Gravity = 0, -1e305"
case_ "gravity 0, -1e305 (overflow)" 2 "set Gravity = 0, -1e305"
case_ "gravity inf" 1 "set Gravity = 0, -1e400"
case_ "Time step = 1e-300" 1 "$(sub Time 'Time step = 1e-300')"
case_ "Time step = 0" 1 "$(sub Time 'Time step = 0')"
case_ "End time = 0" 1 "RAW:$(sub Time 'End time = 0')"
case_ "Target CFL 0.01 with Maximum steps 20" 1 "$(printf 'subsection Time\n set Target CFL = 0.01\n set Maximum steps = 20\nend')"
case_ "Maximum level = 20" 1 "$(sub 'Mesh refinement' 'Maximum level = 20')"
case_ "Maximum level = 21" 1 "$(sub 'Mesh refinement' 'Maximum level = 21')"
case_ "3D, Bulk level = Maximum level = 10" 1 "$(printf 'set Dimension = 3\nset Gravity = 0, 0, -9.81\nsubsection Cavity\n set Lower corner = 0,0,0\n set Upper corner = 1,1,1\n set Coarse subdivisions = 1,1,1\nend\nsubsection Initial liquid\n set Box lower corner = 0,0,0\n set Box upper corner = 0.5,0.5,0.5\nend\nsubsection Mesh refinement\n set Bulk level = 10\n set Maximum level = 10\nend')"
case_ "level set NaN on the wall x = 0" 1 "$(printf 'subsection Initial liquid\n set Shape = expression\n set Level set expression = y - 0.05 + 0.001*log(x)\nend')"
case_ "level set positive everywhere" 1 "$(printf 'subsection Initial liquid\n set Shape = expression\n set Level set expression = 1\nend')"
case_ "level set with a syntax error" 1 "$(printf 'subsection Initial liquid\n set Shape = expression\n set Level set expression = y - (0.05\nend')"
case_ "prescribed velocity NaN after t = 0.005" 1 "$(sub Transport 'Prescribed velocity = 1; sqrt(0.005 - t)')"
case_ "exact final level set 1/0" 1 "$(sub Transport 'Exact final level set = 1/0')"
case_ "initial stress with 2 of 3 components" 1 "$(printf 'subsection Material\n set Polymer viscosity = 1\n set Relaxation time = 0.1\nend\nsubsection Initial liquid\n set Stress = 1; 0\nend')"
case_ "initial stress NaN" 1 "$(printf 'subsection Material\n set Polymer viscosity = 1\n set Relaxation time = 0.1\nend\nsubsection Initial liquid\n set Stress = sqrt(-1); 0; 0\nend')"
case_ "liquid box larger than the cavity (warning)" 1 "$(printf 'subsection Initial liquid\n set Box lower corner = -1, -1\n set Box upper corner = 0.1, 0.1\nend')"
case_ "liquid box outside the cavity" 1 "$(printf 'subsection Initial liquid\n set Box lower corner = 1, 1\n set Box upper corner = 2, 2\nend')"
case_ "liquid ball outside the cavity" 1 "$(printf 'subsection Initial liquid\n set Shape = ball\n set Ball center = 5, 5\nend')"
case_ "liquid ball reaching beyond the cavity (warning)" 1 "$(printf 'subsection Initial liquid\n set Shape = ball\n set Ball center = 0.05, 0.05\nend')"
case_ "Density = -1" 1 "$(sub Material 'Density = -1')"
case_ "Solvent viscosity = 0" 1 "$(sub Material 'Solvent viscosity = 0')"
case_ "Cavity upper corner below lower" 1 "$(sub Cavity 'Upper corner = -1, 1')"
case_ "three gravity components in 2D" 1 "set Gravity = 0, 0, -9.81"
case_ "probe point outside the cavity" 1 "$(sub Postprocess 'Probe point = 5, 5')"
case_ "Bulk level above Maximum level" 1 "$(sub 'Mesh refinement' 'Bulk level = 7')"
case_ "Maximum volume change 1e-6 without correction" 1 "$(printf 'subsection Transport\n set Volume correction = false\nend\nsubsection Health check\n set Maximum volume change = 1e-6\nend')"
case_ "Maximum iterations = 2" 1 "$(sub Solver 'Maximum iterations = 2')"
case_ "Maximum CFL = -1" 1 "$(sub 'Health check' 'Maximum CFL = -1')"
case_ "unknown entry Densty" 1 "$(sub Material 'Densty = 1')"
case_ "malformed value" 1 "$(sub Material 'Density = abc')"
case_ "duplicate entry" 1 "$(printf 'subsection Time\n set End time = 0.01\nend')"
: > empty.prm
case_ "empty parameter file" 1 "" empty.prm
mkdir -p a_directory
case_ "a directory as the parameter file" 1 "" a_directory
case_ "a missing parameter file" 1 "" no_such.prm
case_ "two parameter files" 1 "" case_1.prm case_2.prm
case_ "unknown option --resume" 1 "" --resume x
touch a_file
case_ "output directory below a file" 1 "RAW:set Output directory = a_file/out"
case_ "output directory below a file" 2 "RAW:set Output directory = a_file/out"
mkdir -p locked && touch locked/vefs.lock
case_ "output directory locked by another run" 2 "RAW:set Output directory = locked"
case_ "periodic x- without x+" 1 "$(sub Walls 'x- = periodic')"
case_ "periodic in x and y on 2 ranks" 2 "$(printf 'subsection Walls\n set x- = periodic\n set x+ = periodic\n set y- = periodic\n set y+ = periodic\nend')"
case_ "periodic in x and y on 1 rank" 1 "$(printf 'subsection Walls\n set x- = periodic\n set x+ = periodic\n set y- = periodic\n set y+ = periodic\nend')"
