#!/usr/bin/env bash
# Installs every Debian 12 package PhongLab needs to build, run and test.
# Idempotent: packages already present are skipped. Runs as root or via sudo.
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build pkg-config
  qt6-base-dev qt6-base-dev-tools qt6-base-private-dev libqt6opengl6-dev qt6-charts-dev qt6-svg-dev
  qt6-qpa-plugins libqscintilla2-qt6-dev
  qt6-tools-dev qt6-l10n-tools qt6-translations-l10n   # lupdate/lrelease (translations/), Qt's own German
  libglm-dev libopenmesh-dev
  libgl-dev libegl-dev libgl1-mesa-dri libegl-mesa0   # EGL: rendering with no display server
  desktop-file-utils appstream shared-mime-info libglib2.0-bin # validate the desktop files (tests/install)
  xvfb xauth
  libtinyobjloader-dev libassimp-dev libmeshoptimizer-dev
  libgumbo-dev libarchive-dev           # shaders in HTML projects, submissions in archives (grade)
  clang-14 libclang-rt-14-dev llvm-14   # sanitized build and fuzzers (test.sh, fuzz.sh)
  clang-format-14                       # the tree's format, checked by .ci/run (scripts/format.sh)
  ccache                                # faster rebuilds (build.sh uses it when found)
  chromium                              # grade's report test; the browser PhongLab is proved against (gl.tst_browserdifferential); check --page
  libjs-three                           # three.js r111, the library of the ShaderMaterial test page (gl.tst_pagerun)
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#PACKAGES[@]} packages already installed"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  SUDO="sudo"
fi

echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
