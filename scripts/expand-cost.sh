#!/usr/bin/env bash
# What `#[derive(Lagrangian)]` costs a user's build: macro expansion time with vs without the
# derive on the ellipsoid model (`test-models/derived/src/ellipsoid.rs`), in a scratch crate that
# depends on routh by path with the *default* dev profile (so routh-codegen, routh-symbolic, syn
# and quote run unoptimised, as they do for a user; our workspace's build-override does not apply).
#
# It builds two crates in a scratch workspace, identical except that one derives `Lagrangian` on
# the ellipsoid, then measures each RUNS times:
# 1. the wall clock: a rebuild (touching its source) with `cargo rustc -- -Z time-passes`, the
#    median and minimum `macro_expand_crate` of each and the difference;
# 2. the CPU time (when `perf` is installed): `perf stat -e task-clock` on `rustc -Z no-analysis`
#    (parse and expand, name resolution included, nothing after) of each crate, the minima and
#    the difference — the generator, unoptimised, and what rustc does with its tokens. CPU time
#    is far steadier than the wall clock when other work runs on the machine.
# `-Z` needs nightly; by default the installed stable compiler is used with `RUSTC_BOOTSTRAP=1`
# (the same compiler a user builds with).
#
# Usage: scripts/expand-cost.sh [RUNS]          (default 7)
# Environment:
#   TOOLCHAIN=nightly     run with `cargo +nightly` instead of stable + RUSTC_BOOTSTRAP=1
#   EXPAND_COST_DIR=DIR   scratch workspace (kept; reuse it to skip building the dependencies);
#                         default: a fresh temp dir, removed at exit
#   PROFILE_SNIPPET=TEXT  appended to the scratch Cargo.toml, e.g. to try the README's
#                         `[profile.dev.package.routh-codegen] opt-level = 3`
set -euo pipefail

RUNS=${1:-7}
REPO=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

if [[ -n "${EXPAND_COST_DIR:-}" ]]; then
    DIR=$EXPAND_COST_DIR
    mkdir -p "$DIR"
else
    DIR=$(mktemp -d -t routh-expand-cost.XXXXXX)
    trap 'rm -rf "$DIR"' EXIT
fi
# The scratch build must not inherit ours.
unset CARGO_TARGET_DIR CARGO_BUILD_TARGET_DIR RUSTFLAGS CARGO_ENCODED_RUSTFLAGS CARGO_INCREMENTAL

if [[ -n "${TOOLCHAIN:-}" ]]; then
    CARGO=(cargo "+$TOOLCHAIN")
else
    CARGO=(env RUSTC_BOOTSTRAP=1 cargo)
fi

# The model, verbatim from test-models/derived/src/ellipsoid.rs.
MODEL_ATTR='#[derive(Lagrangian, Debug, Clone)]
#[lagrangian(
    let d = diag(semi_axes.component_mul(semi_axes)),
    let c3 = gamma.dot(d * gamma).sqrt() - offset.dot(gamma),
    let n = grad(c3, gamma),
    kinetic = 0.5 * (omega.dot(inertia * omega) + mass * n.dot(gamma.cross(omega)).powi(2)),
    potential = mass * g * c3,
)]'
MODEL_PLAIN='#[derive(Debug, Clone)]'
MODEL_BODY='pub struct Ellipsoid {
    pub inertia: Matrix3<f64>,
    pub semi_axes: Vector3<f64>,
    pub offset: Vector3<f64>,
    pub mass: f64,
    pub g: f64,
}'

write_crate() { # name, attributes, import
    local name=$1 attrs=$2 import=$3
    mkdir -p "$DIR/$name/src"
    cat >"$DIR/$name/Cargo.toml" <<EOF
[package]
name = "$name"
version = "0.0.0"
edition = "2021"
publish = false

[dependencies]
routh = { path = "$REPO" }
EOF
    printf '#![allow(dead_code, unused_imports)]\n%s\n\n%s\n%s\n' \
        "$import" "$attrs" "$MODEL_BODY" >"$DIR/$name/src/lib.rs"
}

cat >"$DIR/Cargo.toml" <<EOF
[workspace]
members = ["with-derive", "without-derive"]
resolver = "2"
${PROFILE_SNIPPET:-}
EOF
write_crate with-derive "$MODEL_ATTR" 'use routh::{Lagrangian, Matrix3, Vector3};'
write_crate without-derive "$MODEL_PLAIN" 'use routh::{Matrix3, Vector3};'
# Same dependency versions as the repository (and no registry access if they are cached).
[[ -f "$DIR/Cargo.lock" ]] || cp "$REPO/Cargo.lock" "$DIR/Cargo.lock"

cd "$DIR"
echo "scratch workspace: $DIR" >&2
echo "building dependencies (default dev profile)..." >&2
"${CARGO[@]}" build --quiet --workspace 2>&1 | tail -n 20 >&2

# One rebuild of crate $1: prints macro_expand_crate in ms.
measure() {
    local name=$1 out
    touch "$DIR/$name/src/lib.rs"
    out=$("${CARGO[@]}" rustc --quiet -p "$name" --lib -- -Z time-passes 2>&1)
    awk '/macro_expand_crate/ { sub(/;/, "", $2); printf "%.1f\n", $2 * 1000; found = 1 }
         END { if (!found) exit 1 }' <<<"$out" || {
        echo "no macro_expand_crate in the output of -Z time-passes:" >&2
        echo "$out" >&2
        exit 1
    }
}

median() { sort -g | awk '{ a[NR] = $1 } END { print (NR % 2 ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2) }'; }
minimum() { sort -g | head -n 1; }

# Warm-up (first incremental session, file caches).
measure with-derive >/dev/null
measure without-derive >/dev/null

with=() without=()
for ((i = 0; i < RUNS; i++)); do
    with+=("$(measure with-derive)")
    without+=("$(measure without-derive)")
done
mw=$(printf '%s\n' "${with[@]}" | median)
mo=$(printf '%s\n' "${without[@]}" | median)
lw=$(printf '%s\n' "${with[@]}" | minimum)
lo=$(printf '%s\n' "${without[@]}" | minimum)
echo "macro_expand_crate with derive (ms):    ${with[*]}  median $mw, min $lw"
echo "macro_expand_crate without derive (ms): ${without[*]}  median $mo, min $lo"
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores (a busy machine inflates every figure)"
awk -v a="$mw" -v b="$mo" -v c="$lw" -v d="$lo" 'BEGIN {
    printf "derive(Lagrangian) on the ellipsoid adds %.1f ms of macro expansion (median; %.1f ms min to min)\n", a - b, c - d }'

# 2. CPU time of `rustc -Z no-analysis` with and without the derive.
if ! command -v perf >/dev/null; then
    echo "perf not installed: no CPU-time measurement" >&2
    exit 0
fi
OUT=$(mktemp -d -t routh-expand-rustc.XXXXXX)
trap 'rm -rf "$OUT"' EXIT
[[ -n "${EXPAND_COST_DIR:-}" ]] || trap 'rm -rf "$OUT" "$DIR"' EXIT

# The rustc command cargo runs for crate $1, with `-Z no-analysis`, metadata only, no
# incremental cache, its output in $OUT.
command_of() {
    touch "$1/src/lib.rs"
    CARGO_INCREMENTAL=0 "${CARGO[@]}" rustc -v -p "$1" --lib -- -Z no-analysis 2>&1 |
        grep -o 'Running `.*`' | tail -n 1 | sed 's/^Running `//; s/`$//' |
        sed 's/ -C incremental=[^ ]*//; s/--emit=[^ ]*/--emit=metadata/' |
        sed 's/--error-format=json --json=[^ ]*//' |
        sed "s| --out-dir [^ ]*| --out-dir $OUT|"
}
cpu() { RUSTC_BOOTSTRAP=1 perf stat -x, -e task-clock bash -c "$1" 2>&1 >/dev/null | awk -F, '/task-clock/ { print $1 }'; }

with_cmd=$(command_of with-derive)
without_cmd=$(command_of without-derive)
with=() without=()
for ((i = 0; i < RUNS; i++)); do
    with+=("$(cpu "$with_cmd")")
    without+=("$(cpu "$without_cmd")")
done
lw=$(printf '%s\n' "${with[@]}" | minimum)
lo=$(printf '%s\n' "${without[@]}" | minimum)
echo "rustc -Z no-analysis CPU with derive (ms):    ${with[*]}  min $lw"
echo "rustc -Z no-analysis CPU without derive (ms): ${without[*]}  min $lo"
awk -v a="$lw" -v b="$lo" 'BEGIN {
    printf "derive(Lagrangian) on the ellipsoid adds %.1f ms of rustc CPU to parsing and expansion (min to min)\n", a - b }'
