# Dumbbells in the elastic limit (alpha = 0; doc/dumbbells.md): their
# fields are material line elements, so a run with 'Material/Stress model =
# dumbbells' equals the macroscopic one up to round-off, at any number of
# fields. Two scenes, each run with 3 fields and with the macroscopic
# stress: the standing shear wave (shear_wave_2d.prm with the exponential
# update, which the dumbbells use) and the start-up of the channel flow of
# waters_king_2d.prm with alpha = 0, to t = 5. dumbbells_compare.py
# checks the velocity at the probe, the energies and the stress's smallest
# eigenvalue to 1e-8 of their largest values. Both with the nodal stress
# of the vertex average, the dumbbells' only one. The 3D shear wave
# (shear_wave_3d.prm) the same: the fields in 3D; on one rank in both
# variants of this test (periodic walls in 3D need one rank, see
# Parameters::check_for_ranks()).
set -u
variant() { # source prm, output directory, stress model, fields
  sed -e "s|^set Output directory.*|set Output directory = $2|" \
      -e "s|^  set Alpha .*|  set Alpha = 0\n  set Stress model = $3\n  set Dumbbell fields = $4|" \
      -e "s|^  set Stress update = linear|  set Stress update = exponential|" \
      -e "s|^  set End time  = 10|  set End time  = 5|" \
      "$TEST_SOURCE_DIR/$1" > "$2.prm"
  # The nodal stress the dumbbells have (a solid's default is another).
  printf 'subsection Stress\n  set Nodal stress = vertex average\nend\n' \
    >> "$2.prm"
  local launch="${MPIRUN:-}"
  [[ "$1" == *_3d.prm ]] && launch=""
  $launch "$VEFS" "$2.prm" > "$2.log" 2>&1 || echo "$2: exit status $?"
}
for scene in shear_wave_2d waters_king_2d shear_wave_3d; do
  echo "$scene, alpha = 0:"
  variant $scene.prm macroscopic_$scene macroscopic 3
  variant $scene.prm dumbbells_$scene dumbbells 3
  /usr/bin/python3 "$TEST_SOURCE_DIR/dumbbells_compare.py" \
    dumbbells_$scene macroscopic_$scene | sed "s/^/ /"
done
