#!/usr/bin/env bash
# The generator's own CPU time for `#[derive(Lagrangian)]` on the ellipsoid (the model of
# scripts/expand-cost.sh), unoptimised as in a user's debug build: a scratch binary calls
# `routh_codegen::expand_with` once per process (cold, as a proc macro runs), leaving the lexing
# of the generated text out (the compiler does it), and `perf stat -e task-clock` times each run.
# CPU time is far steadier than the wall-clock `macro_expand_crate` of scripts/expand-cost.sh on
# a shared machine, but it leaves out what rustc does with the text (lexing, parsing).
#
# Usage: scripts/expand-cpu.sh [RUNS] [REPO]   (default 11 runs; REPO: a checkout, default this one)
# Environment: EXPAND_CPU_DIR=DIR keeps the scratch crate (reuse it to skip building syn).
set -euo pipefail

RUNS=${1:-11}
REPO=${2:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}
REPO=$(cd "$REPO" && pwd)
if [[ -n "${EXPAND_CPU_DIR:-}" ]]; then
    DIR=$EXPAND_CPU_DIR
    mkdir -p "$DIR"
else
    DIR=$(mktemp -d -t routh-expand-cpu.XXXXXX)
    trap 'rm -rf "$DIR"' EXIT
fi
unset CARGO_TARGET_DIR CARGO_BUILD_TARGET_DIR RUSTFLAGS CARGO_ENCODED_RUSTFLAGS
mkdir -p "$DIR/src"
cat >"$DIR/Cargo.toml" <<EOF
[package]
name = "expand-cpu"
version = "0.0.0"
edition = "2021"
publish = false

[workspace]

[dependencies]
routh-codegen = { path = "$REPO/routh-codegen" }
syn = { version = "2", features = ["full"] }
proc-macro2 = "1"
EOF
cat >"$DIR/src/main.rs" <<'EOF'
const SRC: &str = r#"
#[derive(Lagrangian, Debug, Clone)]
#[lagrangian(
    let d = diag(semi_axes.component_mul(semi_axes)),
    let c3 = gamma.dot(d * gamma).sqrt() - offset.dot(gamma),
    let n = grad(c3, gamma),
    kinetic = 0.5 * (omega.dot(inertia * omega) + mass * n.dot(gamma.cross(omega)).powi(2)),
    potential = mass * g * c3,
)]
pub struct Ellipsoid {
    pub inertia: Matrix3<f64>,
    pub semi_axes: Vector3<f64>,
    pub offset: Vector3<f64>,
    pub mass: f64,
    pub g: f64,
}
"#;
fn main() {
    let di: syn::DeriveInput = syn::parse_str(SRC).expect("the model parses");
    let lex = |_: &str| Some(proc_macro2::TokenStream::new());
    let out = routh_codegen::expand_with(&di, &lex).expect("the model expands");
    std::hint::black_box(out);
}
EOF
[[ -f "$DIR/Cargo.lock" ]] || cp "$REPO/Cargo.lock" "$DIR/Cargo.lock"
(cd "$DIR" && cargo build --quiet 2>&1 | tail -n 20 >&2)
BIN="$DIR/target/debug/expand-cpu"
for ((i = 0; i < RUNS; i++)); do
    perf stat -x, -e task-clock "$BIN" 2>&1 >/dev/null | awk -F, '/task-clock/ { print $1 }'
done | sort -g | awk -v r="$REPO" '{ a[NR] = $1 } END {
    printf "routh_codegen::expand_with on the ellipsoid (%s): CPU min %.1f ms, median %.1f ms over %d runs\n",
        r, a[1], a[int((NR + 1) / 2)], NR }'
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores" >&2
