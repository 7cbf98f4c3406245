# The folders of include/vefs/ and source/ form layers: no include runs from
# a folder to one above it, and every source has its header beside it
# (scripts/check_layers.py, doc/code.md). Needs no run of vefs.
set -u
/usr/bin/python3 "$TEST_SOURCE_DIR/../scripts/check_layers.py" "$TEST_SOURCE_DIR/.."
