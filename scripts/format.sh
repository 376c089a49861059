#!/bin/sh
# Formats PhongLab's C++ with the tree's .clang-format (clang-format 14).
#
#   scripts/format.sh            format every tracked .cpp/.h in place
#   scripts/format.sh --check    list the files that are not formatted; exit 1 if any
#   scripts/format.sh FILE...    format just these
set -eu
cd "$(dirname "$0")/.."
formatter=$(command -v clang-format-14 || command -v clang-format || true)
if [ -z "$formatter" ]; then
    echo "format.sh: clang-format not found (Debian: apt-get install clang-format)" >&2
    exit 2
fi
check=0
if [ "${1:-}" = "--check" ]; then
    check=1
    shift
fi
if [ "$#" -gt 0 ]; then
    files="$*"
else
    files=$(git ls-files '*.cpp' '*.h')
fi
status=0
for file in $files; do
    if [ "$check" -eq 1 ]; then
        if ! "$formatter" --style=file "$file" | cmp -s "$file" -; then
            echo "$file"
            status=1
        fi
    else
        "$formatter" --style=file -i "$file"
    fi
done
exit "$status"
