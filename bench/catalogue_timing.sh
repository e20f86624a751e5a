#!/usr/bin/env bash
# Wall time of the whole default catalogue (the README's main command,
# `brdflut generate --config luts/brdflut.toml`) with 1 and with 2 threads.
#
#   bash bench/catalogue_timing.sh [BRDFLUT] [ROUNDS]
#
# BRDFLUT defaults to ./build/brdflut, ROUNDS to 7. The two thread counts
# alternate so that drifts of the machine's speed hit both alike; the medians
# and their ratio are printed, with every run's wall and CPU seconds, and the
# 2-thread files are checked to be byte-identical to the 1-thread ones.
# Run it from the repository root on an otherwise idle machine.
set -euo pipefail

tool=${1:-./build/brdflut}
rounds=${2:-7}
[[ -x $tool ]] || { echo "catalogue_timing: '$tool' is not an executable (build first)" >&2; exit 2; }
[[ $rounds =~ ^[1-9][0-9]*$ ]] || { echo "catalogue_timing: rounds '$rounds' is not a positive integer" >&2; exit 2; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

declare -A walls
TIMEFORMAT='%R %U %S'
for ((r = 1; r <= rounds; ++r)); do
    for t in 1 2; do
        times=$( { time "$tool" generate --config luts/brdflut.toml -o "$work/t$t" -q --threads "$t" >/dev/null; } 2>&1 )
        read -r wall user sys <<<"$times"
        printf 'round %d, %d thread(s): wall %s s, CPU %s s\n' "$r" "$t" "$wall" "$(awk -v u="$user" -v s="$sys" 'BEGIN {print u + s}')"
        walls[$t]+="$wall "
    done
done

median() { tr ' ' '\n' <<<"$1" | sed '/^$/d' | sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
m1=$(median "${walls[1]}")
m2=$(median "${walls[2]}")
echo "median wall: 1 thread $m1 s, 2 threads $m2 s, speed-up $(awk -v a="$m1" -v b="$m2" 'BEGIN {printf "%.2f", a / b}')"

for f in "$work"/t1/*; do
    cmp -s "$f" "$work/t2/$(basename "$f")" || { echo "catalogue_timing: $(basename "$f") differs between 1 and 2 threads" >&2; exit 1; }
done
echo "files: $(ls "$work/t1" | wc -l), byte-identical for 1 and 2 threads"
