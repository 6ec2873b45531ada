#!/usr/bin/env bash
# Install LinuxCNC's standalone interpreter `rs274` (the reference of tests/gcode/test_rs274_grammar.py) from
# Debian's linuxcnc-uspace package when it is missing. Only .ci/run calls this (make test never installs system
# packages). In CI the rs274 tests fail without it, so this script fails loudly when it cannot install it.
#
# The smallest install: linuxcnc-uspace pulls ~430 packages (GTK, Tk, Mesa, ...; with --no-install-recommends
# still its GUI Depends), but rs274 needs only its own binary and six of the package's libraries (librs274,
# libnml, liblinuxcnchal, liblinuxcncini, libpyplugin, libtooldata) and eight distribution libraries (checked
# with ldd and strace on bookworm: libpython3.11 is loaded for the Python plugin and reads its stdlib). So the
# .deb is downloaded with apt-get download, those files are unpacked to /usr/local, and the runtime
# libraries are installed with --no-install-recommends. Idempotent: nothing happens when rs274 runs.
# PREFIX (default /usr/local) and FORCE=1 (install even when rs274 runs) are for checking this script.
set -euo pipefail
PREFIX=${PREFIX:-/usr/local}
probe() {  # $1 = scratch directory, $2 = the rs274 to run
  printf 'G0 X1\nM2\n' > "$1/p.ngc"
  (cd "$1" && HOME="$1" LD_LIBRARY_PATH="$PREFIX/lib" "$2" -g p.ngc 2>/dev/null | grep -q STRAIGHT_TRAVERSE)
}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
if [ "${FORCE:-0}" != 1 ] && command -v rs274 >/dev/null 2>&1 && probe "$tmp" "$(command -v rs274)"; then
  exit 0
fi
fail() { echo "install-rs274: $*; the rs274 differential (tests/gcode/test_rs274_grammar.py) fails in CI without it" >&2; exit 1; }
[ "$(id -u)" = "0" ] || fail "rs274 not found and not root (apt-get needs root)"
command -v apt-get >/dev/null 2>&1 || fail "rs274 not found and no apt-get (Debian bookworm's linuxcnc-uspace is the source)"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq >/dev/null || fail "apt-get update failed"
apt-get install -y -qq --no-install-recommends libboost-python1.74.0 libpython3.11 libedit2 libtirpc3 libbsd0 \
  libexpat1 zlib1g libtinfo6 >/dev/null || fail "apt-get install of rs274's runtime libraries failed"
(cd "$tmp" && apt-get download -qq linuxcnc-uspace >/dev/null 2>&1) || fail "apt-get download linuxcnc-uspace failed"
dpkg-deb -x "$tmp"/linuxcnc-uspace_*.deb "$tmp/x" || fail "cannot unpack linuxcnc-uspace"
mkdir -p "$PREFIX/bin" "$PREFIX/lib"
install -m 755 "$tmp/x/usr/bin/rs274" "$PREFIX/bin/rs274"
for lib in librs274 libnml liblinuxcnchal liblinuxcncini libpyplugin libtooldata; do
  cp -P "$tmp/x/usr/lib/$lib".so* "$PREFIX/lib/"
done
[ "$PREFIX" != /usr/local ] || ldconfig
probe "$tmp" "$PREFIX/bin/rs274" || fail "rs274 installed in $PREFIX but does not run (ldd $PREFIX/bin/rs274)"
echo "install-rs274: $PREFIX/bin/rs274 from $(basename "$tmp"/linuxcnc-uspace_*.deb)"
