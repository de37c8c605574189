#!/usr/bin/env bash
# The long fuzz run (issue 10 item 6): mutants of every input format and scene files, and special
# files, through `aokit render` for SECONDS (default 3600) on JOBS workers (default: all cores),
# from SEED (default: the date, so each run explores new mutants; pass the seed of a report to
# repeat it). Writes fuzz-report.md (counts per mutation class and outcome, every finding) and
# keeps each finding's input files under fuzz-findings/ for reproduction. Exit 0 when there were no
# findings: no crash, hang, multi-line error, partial output, missing output or silent accept of a
# mutant that must be refused.
#
#   bash scripts/fuzz-long.sh [SECONDS] [SEED] [JOBS]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-3600}
seed=${2:-$(date +%Y%m%d%H%M)}
jobs=${3:-$(nproc)}
out=${FUZZ_OUT:-$root/build}
test -x "$root/build/tests/test_fuzz" || bash "$root/scripts/build.sh"
rm -rf "$out/fuzz-findings"
unset DISPLAY
AOKIT_FUZZ_SECONDS=$seconds AOKIT_FUZZ_SEED=$seed AOKIT_FUZZ_JOBS=$jobs \
AOKIT_FUZZ_REPORT="$out/fuzz-report.md" AOKIT_FUZZ_FINDINGS="$out/fuzz-findings" \
  "$root/build/tests/test_fuzz" --gtest_filter='FuzzLong.*' --gtest_brief=1 > "$out/fuzz-log.txt" 2>&1 && status=0 || status=$?
cat "$out/fuzz-report.md"
exit $status
