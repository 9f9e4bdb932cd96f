#!/usr/bin/env bash
# The CPU time `#[derive(Lagrangian)]` adds to rustc's parsing and expansion of the ellipsoid
# (the scratch crates of scripts/expand-cost.sh), measured with `perf stat -e task-clock` on
# `rustc -Z no-analysis` (parse and expand, name resolution included, nothing after) with and
# without the derive: the generator, unoptimised, and what rustc does with its tokens. CPU time
# is far steadier than the wall-clock `macro_expand_crate` of scripts/expand-cost.sh on a
# shared machine.
#
# Usage: EXPAND_COST_DIR=DIR scripts/expand-cost.sh 1   (builds the scratch crates once)
#        scripts/expand-rustc-cpu.sh DIR [RUNS]           (default 7; prints the minima)
set -euo pipefail

DIR=${1:?usage: scripts/expand-rustc-cpu.sh DIR [RUNS] (DIR: an EXPAND_COST_DIR)}
RUNS=${2:-7}
unset CARGO_TARGET_DIR CARGO_BUILD_TARGET_DIR RUSTFLAGS CARGO_ENCODED_RUSTFLAGS CARGO_INCREMENTAL
export RUSTC_BOOTSTRAP=1
OUT=$(mktemp -d -t routh-expand-rustc.XXXXXX)
trap 'rm -rf "$OUT"' EXIT
cd "$DIR"

# The rustc command cargo runs for crate $1, with `-Z no-analysis`, metadata only, no
# incremental cache, its output in $OUT.
command_of() {
    touch "$1/src/lib.rs"
    cargo rustc -v -p "$1" --lib -- -Z no-analysis 2>&1 |
        grep -o 'Running `.*`' | tail -n 1 | sed 's/^Running `//; s/`$//' |
        sed 's/ -C incremental=[^ ]*//; s/--emit=[^ ]*/--emit=metadata/' |
        sed 's/--error-format=json --json=[^ ]*//' |
        sed "s| --out-dir [^ ]*| --out-dir $OUT|"
}
cpu() { perf stat -x, -e task-clock bash -c "$1" 2>&1 >/dev/null | awk -F, '/task-clock/ { print $1 }'; }

with_cmd=$(command_of with-derive)
without_cmd=$(command_of without-derive)
with=() without=()
for ((i = 0; i < RUNS; i++)); do
    with+=("$(cpu "$with_cmd")")
    without+=("$(cpu "$without_cmd")")
done
lw=$(printf '%s\n' "${with[@]}" | sort -g | head -n 1)
lo=$(printf '%s\n' "${without[@]}" | sort -g | head -n 1)
echo "rustc -Z no-analysis CPU with derive (ms):    ${with[*]}  min $lw"
echo "rustc -Z no-analysis CPU without derive (ms): ${without[*]}  min $lo"
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"
awk -v a="$lw" -v b="$lo" 'BEGIN {
    printf "derive(Lagrangian) on the ellipsoid adds %.1f ms of rustc CPU to parsing and expansion (min to min)\n", a - b }'
