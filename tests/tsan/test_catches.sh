#!/usr/bin/env bash
# ThreadSanitizer catches the race tile_race.cpp injects into the tile store, and stays quiet
# on the same threads storing different tiles. Usage: test_catches.sh zblend_tsan_tile_race
set -uo pipefail
prog=$1
log=$(mktemp)
trap 'rm -f "$log"' EXIT

"$prog" safe >"$log" 2>&1
rc=$?
if [[ $rc -ne 0 ]] || grep -q "ThreadSanitizer" "$log"; then
  cat "$log"
  echo "FAIL: two threads storing different tiles: exit $rc, or a TSan report (expected none)"
  exit 1
fi

"$prog" >"$log" 2>&1
rc=$?
if [[ $rc -eq 0 ]] || ! grep -q "WARNING: ThreadSanitizer: data race" "$log" ||
   ! grep -q "TileSweep::store" "$log"; then
  cat "$log"
  echo "FAIL: two threads storing one tile: exit $rc; expected a TSan data race in TileSweep::store"
  exit 1
fi
echo "ok: TSan reports the injected race in TileSweep::store (exit $rc) and none without it"
