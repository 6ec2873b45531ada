#!/usr/bin/env bash
# Install Debian's linuxcnc-uspace (rs274, the linuxcnc launcher, AXIS's scripts, the sim configurations and
# the linuxcnc Python module) when it is missing, we are root and apt-get exists. Only .ci/run calls this
# (make test never installs system packages). Never fails the build: without LinuxCNC the tests that run it
# (the rs274 differential, the real LinuxCNC session of tests/cli/test_linuxcnc_filter.py) skip with a
# visible reason, and the filter's protocol test runs on its transcription of AXIS's filter_program.
command -v linuxcnc >/dev/null 2>&1 && command -v rs274 >/dev/null 2>&1 && exit 0
if [ "$(id -u)" != "0" ] || ! command -v apt-get >/dev/null 2>&1; then
  echo "install-linuxcnc: linuxcnc not found and cannot apt-get install it (not root or no apt); its tests will skip" >&2
  exit 0
fi
export DEBIAN_FRONTEND=noninteractive
( apt-get update -qq && apt-get install -y -qq linuxcnc-uspace >/dev/null ) \
  || echo "install-linuxcnc: apt-get install linuxcnc-uspace failed; its tests will skip" >&2
exit 0
