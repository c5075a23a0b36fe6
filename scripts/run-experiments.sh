#!/usr/bin/env bash
# Runs every experiment of the paper in full (prt experiment NAME) into one folder, default
# docs/results: CSV files, charts and a summary per experiment. About half an hour on two
# cores; the real runs emulate slow workers and are only faithful on an otherwise idle
# machine, so run nothing else meanwhile. Extra arguments go to every experiment (e.g.
# --runs 5).
#
#   scripts/run-experiments.sh [DIR] [-- extra flags]
set -euo pipefail
cd "$(dirname "$0")/.."
out=docs/results
if [ $# -gt 0 ] && [ "$1" != "--" ]; then
  out=$1
  shift
fi
if [ "${1:-}" = "--" ]; then shift; fi
[ -x build/prt ] || bash scripts/build.sh release
for name in table3 speed-index initial-percent compare scale faults; do
  echo "== prt experiment $name --out $out $*"
  build/prt experiment "$name" --out "$out" "$@" >/dev/null
done
echo "results in $out/ (one NAME.md summary per experiment)"
