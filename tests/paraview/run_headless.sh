#!/bin/sh
# Runs a command under a private Xvfb whose display number the server picks itself (-displayfd),
# so that concurrent runs (ctest -j, other users of xvfb-run -a) never share or race for a display;
# 24-bit colour, which VTK's OpenGL windows need.
set -eu
tmp=$(mktemp -d)
Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp -noreset 3>"$tmp/display" 2>"$tmp/xvfb.log" &
xvfb=$!
trap 'kill $xvfb 2>/dev/null || true; rm -rf "$tmp"' EXIT
i=0
while [ ! -s "$tmp/display" ] && [ $i -lt 200 ]; do
  sleep 0.05
  i=$((i + 1))
done
if [ ! -s "$tmp/display" ]; then
  echo "run_headless: Xvfb did not start:" >&2
  cat "$tmp/xvfb.log" >&2
  exit 1
fi
DISPLAY=":$(head -n 1 "$tmp/display")" "$@"
