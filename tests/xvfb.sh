#!/usr/bin/env bash
# CTest's own X server for the on-screen tests: `start FILE` runs Xvfb on a free display
# (-displayfd) and writes the display's name to FILE (tests read it through AOKIT_XVFB_DISPLAY_FILE);
# `stop FILE` ends that server. Xvfb's output goes to FILE.log, not to CTest's pipes.
set -euo pipefail
cmd=$1
file=$2
case "$cmd" in
  start)
    command -v Xvfb > /dev/null || { echo "Xvfb not found (scripts/setup.sh installs xvfb)" >&2; exit 1; }
    rm -f "$file" "$file.number" "$file.pid"
    # -noreset: a server resets when its last client leaves and refuses connections meanwhile
    setsid Xvfb -displayfd 3 -screen 0 1600x1200x24 -nolisten tcp -noreset 3> "$file.number" > "$file.log" 2>&1 < /dev/null &
    echo $! > "$file.pid"
    for _ in $(seq 1 100); do
      if [ -s "$file.number" ]; then
        echo ":$(tr -d '[:space:]' < "$file.number")" > "$file"
        exit 0
      fi
      sleep 0.1
    done
    echo "Xvfb did not start (see $file.log)" >&2
    exit 1
    ;;
  stop)
    # Wait for the server to be gone: one still exiting removes its socket file, which a new server
    # on the same display number (the next test run) may already have made.
    if [ -f "$file.pid" ]; then
      pid=$(cat "$file.pid")
      kill "$pid" 2> /dev/null || true
      for _ in $(seq 1 100); do
        kill -0 "$pid" 2> /dev/null || break
        sleep 0.1
      done
    fi
    rm -f "$file" "$file.number" "$file.pid"
    ;;
  *) echo "usage: $0 start|stop FILE" >&2; exit 2 ;;
esac
