#!/usr/bin/env bash
# Counts what a user sees at the root of `routh`: the names re-exported from routh-core and by the
# facade (not #[doc(hidden)], not the prelude or __private), and the public modules.
# Usage: scripts/api-count.sh [git-rev]   (default: the working tree)
set -euo pipefail
rev="${1:-}"
show() { if [ -n "$rev" ]; then git show "$rev:$1"; else cat "$1"; fi; }
{ show routh-core/src/lib.rs; echo; echo '//@@FACADE'; show src/lib.rs; } | python3 -c '
import re, sys
src = sys.stdin.read()
src = re.sub(r"pub mod (prelude|__private) \{.*?\n\}", "", src, flags=re.S)
names, mods = set(), set()
hidden = False
for item in re.finditer(r"(#\[doc\(hidden\)\]\s*)?pub (use|mod) ([^;{]*(\{[^}]*\})?[^;]*);", src, flags=re.S):
    if item.group(1):
        continue
    body = item.group(3)
    if item.group(2) == "mod":
        mods.add(body.strip()); continue
    if "{" in body:
        inner = body[body.index("{")+1:body.rindex("}")]
        parts = [p.strip() for p in inner.split(",")]
    else:
        parts = [body.strip()]
    for p in parts:
        if p and p != "*":
            n = p.split("::")[-1]
            if n != "*":
                names.add(n)
print("root names:", len(names)); print(" ".join(sorted(names, key=str.lower)))
print("public modules:", len(mods), " ".join(sorted(mods)))
'
