#!/usr/bin/env bash
# The installed desktop entry, AppStream metainfo and shared-MIME package
# are valid, and the MIME package tells a PhongLab scene from other JSON.
#
#   tests/install/validate-desktop-files.sh BUILD_DIR SOURCE_DIR
#
# The validators come from scripts/setup.sh (desktop-file-utils, appstream,
# shared-mime-info, libglib2.0-bin); exit 77 (CTest: skipped) names any that is missing.
set -euo pipefail
build="$(cd "$1" && pwd)"
source="$(cd "$2" && pwd)"
missing=()
for tool in desktop-file-validate appstreamcli update-mime-database gio; do
  command -v "$tool" >/dev/null || missing+=("$tool")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "SKIP: not installed: ${missing[*]} (scripts/setup.sh installs them)"
  exit 77
fi

work="$(mktemp -d /tmp/phonglab-validate.XXXXXX)"
trap 'rm -rf "$work"' EXIT
DESTDIR="$work/stage" cmake --install "$build" --prefix /usr >/dev/null
share="$work/stage/usr/share"
id=org.phonglab.PhongLab

out="$(desktop-file-validate "$share/applications/$id.desktop" 2>&1)" || true
[ -z "$out" ] || { echo "$out"; echo "FAIL: desktop-file-validate"; exit 1; }
echo "ok: desktop-file-validate $id.desktop"

appstreamcli validate --no-net --no-color "$share/metainfo/$id.metainfo.xml" \
  || { echo "FAIL: appstreamcli validate"; exit 1; }
# The metainfo, desktop entry and icon agree with each other.
appstreamcli validate-tree --no-net --no-color "$work/stage" \
  || { echo "FAIL: appstreamcli validate-tree"; exit 1; }
echo "ok: appstreamcli validate and validate-tree"

# The MIME package compiles, and its magic finds a scene PhongLab wrote and
# leaves other JSON alone (tests/data/scenes: one of each).
# Only freedesktop.org's types and PhongLab's, so that a PhongLab already
# installed on this machine cannot make the checks pass.
mkdir -p "$work/mime"
cp -r "$share/mime/packages" "$work/mime/"
cp /usr/share/mime/packages/freedesktop.org.xml "$work/mime/packages/"
update-mime-database "$work/mime" >/dev/null 2>&1
[ -f "$work/mime/application/vnd.phonglab.scene+json.xml" ] \
  || { echo "FAIL: update-mime-database made no application/vnd.phonglab.scene+json"; exit 1; }
grep -q 'PhongLab' "$work/mime/magic" || { echo "FAIL: no magic for PhongLab scenes"; exit 1; }
echo "ok: the shared-MIME package compiles, with magic for PhongLab scenes"
for scene in "$share"/phonglab/assets/scenes/*.json; do
  head -c 4096 "$scene" | grep -q '"generator": *"PhongLab' \
    || { echo "FAIL: $(basename "$scene") lacks the \"generator\" its MIME magic matches"; exit 1; }
done
echo "ok: every shipped scene carries the generator the MIME magic matches"

# What a desktop (GIO) says about a scene and about other JSON.
content_type() {
  XDG_DATA_HOME="$work/none" XDG_DATA_DIRS="$work" \
    gio info -a standard::content-type "$1" | sed -n 's/^ *standard::content-type: //p'
}
grep -v '"generator"' "$share/phonglab/assets/scenes/sphere.json" > "$work/other.json"
scene_type="$(content_type "$share/phonglab/assets/scenes/sphere.json")"
other_type="$(content_type "$work/other.json")"
[ "$scene_type" = "application/vnd.phonglab.scene+json" ] \
  || { echo "FAIL: a PhongLab scene reads as '$scene_type'"; exit 1; }
[ "$other_type" = "application/json" ] || { echo "FAIL: other JSON reads as '$other_type'"; exit 1; }
echo "ok: a scene is $scene_type, other JSON stays $other_type"
