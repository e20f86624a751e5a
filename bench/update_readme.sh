#!/usr/bin/env bash
# Rewrites the benchmark figures of docs/performance.md from a fresh run of
# the benchmarks (never by hand):
#
#   bash bench/update_readme.sh [BUILD_DIR] [ROUNDS]
#
# BUILD_DIR defaults to ./build, ROUNDS (of brdflut_dfg_race) to 9. Runs
# brdflut_dfg_race (ggx_dfg against the 1024-sample estimator, 1 and 2
# threads) and brdflut_table_report --no-mc (every table and its error against
# --quality reference), keeps their output in bench/last_run.txt, and renders
# it into the block between the markers of docs/performance.md with
# brdflut_readme_figures. tests/test_readme.cpp checks the block. Run it
# from the repository root on an otherwise idle machine.
set -euo pipefail

build=${1:-./build}
rounds=${2:-9}
for p in brdflut_dfg_race brdflut_table_report brdflut_readme_figures; do
    [[ -x $build/bench/$p ]] || { echo "update_readme: $build/bench/$p is missing (build the bench targets first)" >&2; exit 2; }
done
[[ $rounds =~ ^[1-9][0-9]*$ ]] || { echo "update_readme: rounds '$rounds' is not a positive integer" >&2; exit 2; }

out=$(mktemp)
trap 'rm -f "$out"' EXIT
"$build/bench/brdflut_dfg_race" --rounds "$rounds" | tee "$out"
"$build/bench/brdflut_table_report" --no-mc | tee -a "$out"
"$build/bench/brdflut_readme_figures" docs/performance.md "$out"
cp "$out" bench/last_run.txt
echo "update_readme: docs/performance.md rewritten from bench/last_run.txt"
