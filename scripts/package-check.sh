#!/usr/bin/env bash
# The package on a fresh Debian 12: debootstrap a minimal bookworm into a
# folder, `apt-get install ./phonglab_*.deb` there, and show that
#   - the desktop lists PhongLab (GIO names it for PhongLab scenes and
#     meshes) and its menu entry launches the editor window (under Xvfb);
#   - `phonglab check` and `render` work with no X server, as over SSH.
#
#   scripts/package-check.sh [DEB]      (default: build/phonglab_*.deb from
#                                        scripts/package.sh; needs root and
#                                        Debian's mirror; ~10 minutes)
# The chroot stays in $PHONGLAB_CHROOT (default /tmp/phonglab-bookworm) for
# reuse; delete it for a fresh start. Its /proc, /sys and /dev are mounted
# only inside a private mount and PID namespace that ends with the script,
# so nothing is ever mounted over the host's folders or left behind, and no
# process outside is signalled.
set -euo pipefail
cd "$(dirname "$0")/.."
deb="$(realpath "${1:-$(ls build/phonglab_*.deb | head -n 1)}")"
root="${PHONGLAB_CHROOT:-/tmp/phonglab-bookworm}"
[ "$(id -u)" -eq 0 ] || { echo "package-check: needs root (debootstrap, chroot)" >&2; exit 1; }
command -v debootstrap >/dev/null \
  || DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends debootstrap

if [ ! -x "$root/usr/bin/apt-get" ]; then
  echo "package-check: debootstrap bookworm into $root"
  debootstrap --variant=minbase bookworm "$root" http://deb.debian.org/debian >/dev/null
fi
if [ -z "${PHONGLAB_PACKAGE_CHECK_NAMESPACE:-}" ]; then
  exec env PHONGLAB_PACKAGE_CHECK_NAMESPACE=1 PHONGLAB_CHROOT="$root" \
    unshare --mount --propagation private --pid --fork bash "$0" "$deb"
fi
# In the private namespace: these mounts die with it.
mount -t proc proc "$root/proc"
mount -t sysfs sysfs "$root/sys"
mount --rbind /dev "$root/dev"
cp "$deb" "$root/tmp/"
in_root() { chroot "$root" env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root \
  DEBIAN_FRONTEND=noninteractive "$@"; }

echo "package-check: apt-get install ./$(basename "$deb")"
in_root apt-get update -qq
# --reinstall: a rebuilt package of the same version replaces the last one.
in_root apt-get install -y -qq --reinstall "/tmp/$(basename "$deb")" >/dev/null
# What a desktop brings: its application and MIME databases, an X server.
in_root apt-get install -y -qq desktop-file-utils shared-mime-info libglib2.0-bin \
  xvfb xauth x11-utils >/dev/null
# --version names the package's version.
got="$(in_root phonglab --version)"
want="phonglab $(dpkg-deb --field "$deb" Version)"
[ "$got" = "$want" ] || { echo "FAIL: --version says '$got', the package is '$want'"; exit 1; }
echo "$got"

echo "package-check: the desktop's application list"
in_root gio mime application/vnd.phonglab.scene+json | tee /tmp/phonglab-gio.txt
grep -q "org.phonglab.PhongLab.desktop" /tmp/phonglab-gio.txt \
  || { echo "FAIL: GIO lists no PhongLab for its scenes"; exit 1; }
in_root gio mime model/obj | grep -q "org.phonglab.PhongLab.desktop" \
  || { echo "FAIL: GIO lists no PhongLab for OBJ meshes"; exit 1; }

echo "package-check: no X server, as over SSH"
in_root sh -c 'cd /tmp && phonglab check /usr/share/phonglab/assets/scenes/check.json --size 320x240 \
  && phonglab render /usr/share/phonglab/assets/scenes/default.json -o /tmp/default.png \
  && test -s /tmp/default.png && echo "render: /tmp/default.png"'

echo "package-check: launch from the menu entry (gio launch, under Xvfb)"
in_root xvfb-run -a -s "-screen 0 1600x1000x24" sh -c '
  gio launch /usr/share/applications/org.phonglab.PhongLab.desktop &
  # The editor window: titled PhongLab and larger than Qt'"'"'s 1x1 helpers.
  window() { xwininfo -root -tree | grep "PhongLab" | awk '"'"'match($0, / [0-9]+x[0-9]+\+/) {
    split(substr($0, RSTART + 1, RLENGTH - 2), size, "x"); if (size[1] >= 400) { print; exit } }'"'"'; }
  for i in $(seq 1 60); do
    found="$(window)"
    if [ -n "$found" ]; then echo "window: $found"; pkill -x phonglab; exit 0; fi
    sleep 1
  done
  xwininfo -root -tree | grep -i phonglab
  echo "FAIL: no PhongLab window within 60 s"; pkill -x phonglab; exit 1'
echo "PASS: installed on a fresh Debian 12, listed by the desktop, launched from its menu entry, checked with no X server"
