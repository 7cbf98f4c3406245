# The 3D renderer's surface (scripts/render_surfaces.py, marching
# tetrahedra in scripts/vefs_tools/isosurface.py): the volume inside the
# zero surface of a sphere's distance sampled on uniform meshes of the unit
# cube (h = 1/8, 1/16, 1/32) against the exact 4/3 pi R^3, and its
# observed order (at least 1.8, or the script exits 1). Needs no run of
# vefs; numpy and matplotlib come with scripts/setup.sh.
set -u
/usr/bin/python3 "$TEST_SOURCE_DIR/../scripts/render_surfaces.py" --self-test
