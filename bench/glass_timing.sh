#!/usr/bin/env bash
# Wall time of the glass tables on 2 threads: the default glass set
# (ggx_glass_albedo, ggx_glass_albedo_inside and their averages) and the four
# Cycles glass tables of `--preset cycles`; then, unless --no-reference, the
# same at `--quality reference` (the values are checked against those by
# ./build/bench/brdflut_table_report, which compares every texel of every
# table with its reference run).
#
#   bash bench/glass_timing.sh [BRDFLUT] [--no-reference]
#
# Run it from the repository root on an otherwise idle machine.
set -euo pipefail

tool=${1:-./build/brdflut}
reference=1
[[ ${2:-} == --no-reference ]] && reference=0
[[ -x $tool ]] || { echo "glass_timing: '$tool' is not an executable (build first)" >&2; exit 2; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
TIMEFORMAT='%R %U %S'

default_set="ggx_glass_albedo ggx_glass_albedo_inside ggx_glass_albedo_avg ggx_glass_albedo_avg_inside"
cycles_set="cycles_ggx_glass_e cycles_ggx_glass_inv_e cycles_ggx_glass_e_avg cycles_ggx_glass_inv_e_avg"

run() {  # name, quality, ids...
    local name=$1 quality=$2
    shift 2
    local times
    # shellcheck disable=SC2086
    times=$( { time "$tool" generate "$@" --quality "$quality" -o "$work/$name-$quality" -q --threads 2 >/dev/null; } 2>&1 )
    read -r wall user sys <<<"$times"
    printf '%s (%s): wall %s s, CPU %s s\n' "$name" "$quality" "$wall" "$(awk -v u="$user" -v s="$sys" 'BEGIN {print u + s}')"
}

# shellcheck disable=SC2086
run default default $default_set
# shellcheck disable=SC2086
run cycles default $cycles_set
if ((reference)); then
    # shellcheck disable=SC2086
    run default reference $default_set
    # shellcheck disable=SC2086
    run cycles reference $cycles_set
fi
