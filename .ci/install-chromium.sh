#!/usr/bin/env bash
# Install Debian's chromium for the HTML report browser tests (tests/report/test_html.py) when it is
# missing, we are root and apt-get exists. Only .ci/run calls this (make test never installs system
# packages). Never fails the build: without chromium those tests skip with a visible reason.
command -v chromium >/dev/null 2>&1 || command -v chromium-browser >/dev/null 2>&1 \
  || command -v google-chrome >/dev/null 2>&1 && exit 0
if [ "$(id -u)" != "0" ] || ! command -v apt-get >/dev/null 2>&1; then
  echo "install-chromium: chromium not found and cannot apt-get install it (not root or no apt); browser tests will skip" >&2
  exit 0
fi
export DEBIAN_FRONTEND=noninteractive
( apt-get update -qq && apt-get install -y -qq chromium >/dev/null ) \
  || echo "install-chromium: apt-get install chromium failed; browser tests will skip" >&2
exit 0
