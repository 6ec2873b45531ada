#!/usr/bin/env bash
# Install Debian's chromium for the HTML report browser tests (tests/report/test_html.py and
# tests/report/test_html_view.py, the interactive view: load, canvas, click, screenshots in build/screenshots/)
# when it is missing. Only .ci/run calls this (make test never installs system packages: locally, without
# chromium those tests skip). In CI (CI=true) the interactive-view tests fail without chromium, so this
# script fails loudly when it cannot install it, as .ci/install-rs274.sh does for rs274.
set -euo pipefail
if command -v chromium >/dev/null 2>&1 || command -v chromium-browser >/dev/null 2>&1 \
  || command -v google-chrome >/dev/null 2>&1; then
  exit 0
fi
fail() { echo "install-chromium: $*; the browser tests of the HTML report fail in CI without it" >&2; exit 1; }
[ "$(id -u)" = "0" ] || fail "chromium not found and not root (apt-get needs root)"
command -v apt-get >/dev/null 2>&1 || fail "chromium not found and no apt-get"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq >/dev/null || fail "apt-get update failed"
apt-get install -y -qq chromium >/dev/null || fail "apt-get install chromium failed"
