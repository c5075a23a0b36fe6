#!/bin/sh
# One comparison of PRT against POV-Ray 3.7 (docs/povray-mapping.md), asserting its threshold.
#   povray_compare_test.sh PRT SCENE OUTDIR MIN_PSNR_DB MAX_DIFFERING_PERCENT [COMPARE ARGS...]
# Runs `prt compare SCENE --out OUTDIR [ARGS]` and fails unless PSNR >= MIN_PSNR_DB and at most
# MAX_DIFFERING_PERCENT % of the pixels differ by more than the tolerance. Exits 77 (CTest's
# SKIP_RETURN_CODE) when povray is not installed.
set -eu

prt=$1 scene=$2 out=$3 min_psnr=$4 max_percent=$5
shift 5

if ! command -v povray >/dev/null 2>&1; then
  echo "SKIP: povray is not installed (Debian: apt-get install povray)"
  exit 77
fi

set +e
result=$("$prt" compare "$scene" --out "$out" "$@" 2>&1)
status=$?
set -e
echo "$result"
if [ "$status" -ne 0 ]; then
  echo "FAIL: prt compare exited with code $status" >&2
  exit 1
fi

# "  PSNR 42.56 dB, 0.45 % of pixels differ by more than 8/255"; PSNR may be "inf".
line=$(echo "$result" | grep "PSNR " || true)
psnr=$(echo "$line" | awk '{print $2}')
percent=$(echo "$line" | awk '{print $4}')
if [ -z "$psnr" ] || [ -z "$percent" ]; then
  echo "FAIL: no PSNR line in the output of prt compare" >&2
  exit 1
fi
verdict=$(awk -v p="$psnr" -v d="$percent" -v minp="$min_psnr" -v maxd="$max_percent" 'BEGIN {
  ok_psnr = (p == "inf") || (p + 0 >= minp + 0)
  ok_diff = (d + 0 <= maxd + 0)
  print (ok_psnr && ok_diff) ? "pass" : "fail"
}')
echo "threshold: PSNR >= $min_psnr dB, differing <= $max_percent %: $verdict"
[ "$verdict" = pass ] || { echo "FAIL: see $out for PRT | POV-Ray | difference" >&2; exit 1; }
