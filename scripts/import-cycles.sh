#!/usr/bin/env bash
# Detects import cycles among routh-core's top-level modules: module A depends on module B when
# code (not comments) in A's files names `crate::B…`, or a name the crate root re-exports from B
# (`crate::Routhian` is `model`). Exits 1 and prints the cycle's modules if the graph has one.
#
# Usage: scripts/import-cycles.sh [path/to/src]   (default routh-core/src)
set -euo pipefail
cd "$(dirname "$0")/.."
src="${1:-routh-core/src}"
lib="$src/lib.rs"

# Code without comments, one line per file part joined with spaces.
code() { sed -e 's://.*$::' "$@" | tr '\n' ' '; }

modules=$(grep -oE '^(pub(\([a-z]+\))? )?mod [a-z_0-9]+;' "$lib" | sed -E 's/.*mod ([a-z_0-9]+);/\1/')

# name -> module, from `pub use m::{a, b};` and `pub use m::a;` at the root.
reexports=$(code "$lib" | grep -oE 'pub use [a-z_0-9]+::(\{[^}]*\}|[A-Za-z_0-9]+)' |
  sed -E 's/pub use ([a-z_0-9]+)::\{?([^}]*)\}?/\1 \2/' |
  awk '{m=$1; $1=""; n=split($0, a, /[ ,]+/); for (i=1;i<=n;i++) if (a[i]!="") print a[i], m}')

edges=""
for m in $modules; do
  files=()
  if [ -f "$src/$m.rs" ]; then files+=("$src/$m.rs"); fi
  if [ -d "$src/$m" ]; then while IFS= read -r f; do files+=("$f"); done < <(find "$src/$m" -name '*.rs' | sort); fi
  if [ ${#files[@]} -eq 0 ]; then continue; fi
  names=$(code "${files[@]}" | { grep -oE 'crate::(\{[^}]*\}|[A-Za-z_0-9]+)' || true; } |
    sed -E 's/crate::\{?([^}]*)\}?/\1/' | tr ',' '\n' | sed -E 's/^ *([A-Za-z_0-9]+).*/\1/' | sort -u)
  for n in $names; do
    target=""
    if echo "$modules" | grep -qx "$n"; then
      target=$n
    else
      target=$(echo "$reexports" | awk -v n="$n" '$1==n {print $2; exit}')
    fi
    if [ -n "$target" ] && [ "$target" != "$m" ]; then
      edges+="$m $target"$'\n'
    fi
  done
done

echo "$edges" | sort -u | awk '
  NF == 2 { e[$1, $2] = 1; v[$1] = 1; v[$2] = 1 }
  END {
    # Transitive closure (Floyd–Warshall); a module reaching itself is on a cycle.
    for (k in v) for (i in v) if (e[i, k]) for (j in v) if (e[k, j]) e[i, j] = 1
    bad = 0
    for (i in v) if (e[i, i]) { printf "import cycle through `%s`:", i; for (j in v) if (e[i, j] && e[j, i]) printf " %s", j; print ""; bad = 1 }
    if (bad) exit 1
    print "no import cycles among the modules of the crate"
  }'
