#!/usr/bin/env bash
# Counts what a user of `routh` sees: the names at its root (re-exported from routh-core and by the
# facade; not #[doc(hidden)], not the prelude or __private), the public modules, and the names
# that only a public module holds (`routh::certify::MIN_WIDTH`, `routh::sim::attitude::…`).
# Fails when the total is over BUDGET: a new public name is a decision, so raise the budget in
# the same commit, or hide an internal (`pub(crate)`, `#[doc(hidden)]`) instead.
# Usage: scripts/api-count.sh [git-rev]   (default: the working tree)
set -euo pipefail
cd "$(dirname "$0")/.."
# 133 after hiding internals; +13 for the figures' one style (the module `style`, its table and
# constants, which the Python package reads too; `plot::png_from_svg`,
# `plot::with_circle_verdicts`); +2 for periodic families (`switch_branch`, `axial_symmetry`);
# +2 for families in a parameter (`continue_orbit_in`, `OrbitParameterFamily`); +2 for run
# control (`RunControl`, `Progress`); +4 for the one writer of every file (the module `files`,
# `files::write_file`, `files::Staged`, `files::WriteError`); −3 for the deprecated names
# removed (`fluid::FluidError`, `stability::classify_with_krein`, `families::CheckedDiagram`; the
# other removed aliases were hidden and not counted); +9 for the binding names of ARCHITECTURE
# §5h (`orbit_nonlinear_stability` and its options, report, verdict and resonance;
# `orbit_chart` and its options, chart and curve); +3 for the one tick format both renderers
# use (`style::tick_label`, `style::decade_label`) and the page width (`style::PAGE_WIDTH_IN`).
# +1: the orbit chart's SVG (`plot::orbit_chart_svg`), as every other figure kind has.
# +5 for one keyword surface per analysis, shared by Python and the command line (the module
# `options`: `Options`, `OptionError`, `keywords`, `overlay`).
BUDGET=171
rev="${1:-}"
show() { if [ -n "$rev" ]; then git show "$rev:$1" 2>/dev/null || true; else cat "$1" 2>/dev/null || true; fi; }
export -f show
export rev
BUDGET="$BUDGET" python3 - <<'PY'
import os, re, subprocess, sys

def show(path):
    return subprocess.run(["bash", "-c", 'show "$0"', path], capture_output=True, text=True).stdout

def strip_inline_mods(src):
    # `pub mod prelude { … }`, `pub mod __private { … }` and `mod tests { … }` are not API.
    src = re.sub(r"pub mod (prelude|__private) \{.*?\n\}", "", src, flags=re.S)
    return re.sub(r"#\[cfg\(test\)\]\s*mod \w+ \{.*?\n\}", "", src, flags=re.S)

# An item at the start of a line, with the attributes and doc comments just above it.
ITEM = re.compile(
    r"^((?:[ \t]*(?:#\[[^\n]*\]|///[^\n]*|//![^\n]*)[ \t]*\n)*)"
    r"pub (use|mod|fn|struct|enum|trait|type|const|static)\s+",
    re.M,
)

def items(src):
    """(kind, names, hidden, deprecated) for each top-level `pub` item of a source file."""
    src = strip_inline_mods(src)
    out = []
    for m in ITEM.finditer(src):
        attrs, kind = m.group(1), m.group(2)
        hidden = "doc(hidden)" in attrs
        deprecated = "#[deprecated" in attrs
        rest = src[m.end():]
        if kind == "use":
            body = rest[: rest.index(";")]
            if "{" in body:
                inner = body[body.index("{") + 1 : body.rindex("}")]
                parts = [p.strip() for p in inner.split(",")]
            else:
                parts = [body.strip()]
            names = []
            for p in parts:
                if not p or p.endswith("*"):
                    continue
                names.append(p.split(" as ")[-1].split("::")[-1].strip())
        else:
            name = re.match(r"\w+", rest)
            names = [name.group(0)] if name else []
        out.append((kind, names, hidden, deprecated))
    return out

def module_file(crate_dir, parts):
    """The file of module `parts` under `crate_dir/src` (`a/b.rs` or `a/b/mod.rs`)."""
    base = os.path.join(crate_dir, "src", *parts)
    for path in (base + ".rs", os.path.join(base, "mod.rs")):
        text = show(path)
        if text:
            return text
    return ""

root, modules, deprecated = set(), [], set()
module_names = {}  # name -> first module path holding it
for crate_dir, prefix in (("routh-core", ""), (".", "")):
    lib = show(os.path.join(crate_dir, "src", "lib.rs"))
    stack = []
    for kind, names, hidden, dep in items(lib):
        if hidden:
            continue
        if kind == "mod":
            stack += [(n,) for n in names]
        else:
            root.update(names)
            if dep:
                deprecated.update(names)
    # The public modules, depth first, with their public submodules.
    while stack:
        parts = stack.pop(0)
        modules.append("::".join(parts))
        for kind, names, hidden, dep in items(module_file(crate_dir, list(parts))):
            if hidden:
                continue
            if kind == "mod":
                stack += [parts + (n,) for n in names]
                continue
            for n in names:
                module_names.setdefault(n, "::".join(parts))
                if dep:
                    deprecated.add(n)

only_modules = sorted(set(module_names) - root, key=str.lower)
total = len(root) + len(modules) + len(only_modules)
budget = int(os.environ["BUDGET"])
print("root names:", len(root))
print(" ".join(sorted(root, key=str.lower)))
print("public modules:", len(modules), " ".join(sorted(modules)))
print("names only in public modules:", len(only_modules))
print(" ".join(f"{module_names[n]}::{n}" for n in only_modules))
print("deprecated (counted above):", len(deprecated), " ".join(sorted(deprecated, key=str.lower)))
print(f"total: {total} (budget {budget})")
if total > budget:
    print(f"over the budget by {total - budget}: hide an internal or raise BUDGET in scripts/api-count.sh", file=sys.stderr)
    sys.exit(1)
PY
