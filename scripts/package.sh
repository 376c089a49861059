#!/usr/bin/env bash
# Builds the Debian package build/phonglab_VERSION_ARCH.deb (CPack, see
# cmake/Package.cmake) and runs lintian on it: no error may remain.
#
#   scripts/package.sh
#   sudo apt-get install ./build/phonglab_*.deb     # then: PhongLab in the menu
#
# scripts/package-check.sh installs the package on a fresh Debian 12 made
# with debootstrap and uses it there.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh

# dpkg-shlibdeps (the package's library dependencies) and lintian.
tools=(dpkg-dev lintian)
missing=()
for p in "${tools[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO=sudo
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

rm -f build/phonglab_*.deb
(cd build && cpack -G DEB)
deb="$(ls build/phonglab_*.deb)"
echo "package: $deb"
dpkg-deb --field "$deb" Package Version Depends
# Errors fail the build; warnings and notes are printed for a person to read.
lintian --fail-on error --tag-display-limit 0 "$deb"
echo "lintian: no errors"
