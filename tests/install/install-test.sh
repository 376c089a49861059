#!/usr/bin/env bash
# An installed PhongLab on a moved prefix, with the source and build trees
# out of reach, renders and checks scenes against the exact reference.
#
#   tests/install/install-test.sh BUILD_DIR SOURCE_DIR VERSION
#
# Installs into a DESTDIR, moves the prefix elsewhere, then runs the
# installed binary in a private mount namespace where empty folders cover
# the source and the build trees, with no display server. Exit 77 (CTest:
# skipped) only where no mount namespace can be made (not root).
set -euo pipefail
build="$(cd "$1" && pwd)"
source="$(cd "$2" && pwd)"
version="$3"

work="$(mktemp -d /tmp/phonglab-install.XXXXXX)"
trap 'rm -rf "$work"' EXIT
DESTDIR="$work/stage" cmake --install "$build" --prefix /usr >/dev/null
mkdir -p "$work/moved"
mv "$work/stage/usr" "$work/moved/prefix"
# The wrong shader that must fail the same check, copied before the source
# tree is hidden.
cp "$source/tests/data/shaders/wrong_normal_modelview.vert" "$work/wrong.vert"

if ! unshare -m --propagation private true 2>/dev/null; then
  echo "SKIP: no private mount namespace (unshare -m needs root) to hide the build tree"
  exit 77
fi

cat > "$work/inside.sh" <<'INSIDE'
set -euo pipefail
work="$1"; source="$2"; build="$3"; version="$4"
mount -t tmpfs tmpfs "$source"
case "$build/" in "$source"/*) ;; *) mount -t tmpfs tmpfs "$build" ;; esac
[ -z "$(ls -A "$source")" ] || { echo "FAIL: the source tree is still visible"; exit 1; }
prefix="$work/moved/prefix"
exe="$prefix/bin/phonglab"
scenes="$prefix/share/phonglab/assets/scenes"
unset DISPLAY WAYLAND_DISPLAY QT_QPA_PLATFORM PHONGLAB_SHADER_DIR PHONGLAB_ASSET_DIR
export PHONGLAB_CACHE_DIR="$work/cache"

got="$("$exe" --version)"
[ "$got" = "phonglab $version" ] || { echo "FAIL: --version says '$got', the package is $version"; exit 1; }
echo "ok: $got"

"$exe" render "$scenes/default.json" -o "$work/default.png" --size 320x240
[ -s "$work/default.png" ] || { echo "FAIL: render wrote no image"; exit 1; }
echo "ok: render of the default scene"

# A display that cannot be reached (a stale DISPLAY over SSH) falls back to EGL.
DISPLAY=:987 "$exe" render "$scenes/default.json" -o "$work/stale.png" --size 320x240 2>/dev/null \
  || { echo "FAIL: render with an unreachable DISPLAY"; exit 1; }
cmp -s "$work/default.png" "$work/stale.png" || { echo "FAIL: the fallback rendered other pixels"; exit 1; }
echo "ok: render with an unreachable DISPLAY falls back to EGL, same pixels"

# The shipped shaders against the exact reference: must match.
"$exe" check "$scenes/check.json" --size 320x240 > "$work/check.txt" \
  || { cat "$work/check.txt"; echo "FAIL: the installed shaders do not match the reference"; exit 1; }
head -n 2 "$work/check.txt"
echo "ok: check of the shipped shaders"

# A classic mistake: the same check must fail and name it.
status=0
"$exe" check "$scenes/check.json" --size 320x240 --vertex "$work/wrong.vert" > "$work/wrong.txt" \
  || status=$?
[ "$status" = 1 ] || { cat "$work/wrong.txt"; echo "FAIL: a wrong normal matrix passed (exit $status)"; exit 1; }
grep -q "normal-matrix" "$work/wrong.txt" \
  || { cat "$work/wrong.txt"; echo "FAIL: the wrong normal matrix was not named"; exit 1; }
echo "ok: a wrong normal matrix fails the check and is named"

"$exe" mesh-info "$prefix/share/phonglab/assets/meshes/tree.obj" > "$work/info.txt"
grep -q "triangles" "$work/info.txt" || { cat "$work/info.txt"; echo "FAIL: mesh-info"; exit 1; }
echo "ok: mesh-info of a shipped mesh"
INSIDE
unshare -m --propagation private bash "$work/inside.sh" "$work" "$source" "$build" "$version"
echo "PASS: installed on a moved prefix, source and build trees hidden, no display server"
