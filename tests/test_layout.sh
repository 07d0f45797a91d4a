#!/usr/bin/env bash
# The source layout rules of issue 22 (tests/check_layout.py says each rule and
# why): at most 25 .c files a folder of src/, src/trace/trace.c under 500
# lines, no function over 100 lines, no *_internal.h included from another
# folder, no include circle across folders. Debian's python3, standard
# library only.
# usage: test_layout.sh SOURCE_DIR
set -u
if [ $# -ne 1 ]; then
    echo "usage: test_layout.sh SOURCE_DIR" >&2
    exit 2
fi
python=$(command -v /usr/bin/python3 || command -v python3) || {
    echo "layout: no python3" >&2
    exit 2
}
exec "$python" "$(dirname "$0")/check_layout.py" "$1"
