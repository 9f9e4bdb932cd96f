#!/usr/bin/env python3
"""The layering check: no import cycles between the source files of any crate of the workspace.

A file A *uses* a file B of the same crate when code in A names an item that B defines: through a
`use` declaration (`use crate::model::Routhian;`, `use super::{a, b::C};`) or a path in code
(`crate::sim::simulate(…)`, `super::Options`, `child::f()` after `use super::child;`). Names are
followed through re-exports (`pub use model::Routhian;` at a crate root sends `crate::Routhian`
to `model.rs`), so re-exports themselves are name routing, not uses. A `mod` declaration is not a
use either: a parent that declares a child does not depend on it until it names one of its items.

The rule: the "uses" graph between the files of each crate is acyclic. Every file has a level (the
files it uses sit below it), so a file can be read, tested and moved knowing only what is below.
Crates are acyclic by construction (cargo refuses a cycle between packages).

Prints every cycle (each file of a strongly connected component and the names behind each edge)
and exits 1 if there is one; otherwise prints one line per crate and exits 0.

Usage: scripts/layering.py [crate-dir …]   (default: every member of the workspace and the root)
"""
import os
import re
import sys
from collections import defaultdict

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

IDENT = r"[A-Za-z_][A-Za-z_0-9]*"
ITEM_RE = re.compile(
    r"\b(?:fn|struct|enum|trait|type|const|static|union)\s+(" + IDENT + r")"
    r"|\bmacro_rules!\s*(" + IDENT + r")"
)
KEYWORDS = {"crate", "super", "self"}


def strip(text):
    """Blanks out comments, string and character literals (newlines kept)."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            depth, j = 1, i + 2
            while j < n and depth:
                if text.startswith("/*", j):
                    depth, j = depth + 1, j + 2
                elif text.startswith("*/", j):
                    depth, j = depth - 1, j + 2
                else:
                    j += 1
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == "r" and re.match(r'r#*"', text[i:]) and not re.match(r"[A-Za-z_0-9]", text[i - 1 : i] or " "):
            hashes = re.match(r"r(#*)\"", text[i:]).group(1)
            end = text.find('"' + hashes, i + 2 + len(hashes))
            j = n if end < 0 else end + 1 + len(hashes)
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == '"':
            j = i + 1
            while j < n and text[j] != '"':
                j += 2 if text[j] == "\\" else 1
            j += 1
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == "'":
            m = re.match(r"'(\\[^']+|[^\\'])'", text[i:])
            if m:
                out.append(" " * len(m.group(0)))
                i += len(m.group(0))
            else:
                out.append(c)
                i += 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


class Module:
    def __init__(self, path, file, parent):
        self.path = path  # tuple of names from the crate root
        self.file = file  # the source file the module's code is in
        self.parent = parent
        self.children = {}  # name -> Module
        self.items = set()  # names defined here
        self.imports = {}  # name -> (segments, glob?, public?) — `use` declarations
        self.globs = []  # segments of `use …::*;`
        self.uses = []  # (segments, line) named by code in this module (not re-exports)


def flatten_use(tree):
    """`a::{b, c::{d as e, *}}` -> [(['a','b'], 'b'), (['a','c','d'], 'e'), (['a','c'], '*')]."""
    tree = re.sub(r"\s+", " ", tree).strip()
    out = []

    def go(prefix, s):
        s = s.strip()
        if not s:
            return
        if s.startswith("::"):
            s = s[2:]
        brace = s.find("{")
        if brace >= 0 and "::" in s[:brace] or s.startswith("{"):
            head = s[:brace].rstrip(":").strip()
            segs = [x.strip() for x in head.split("::") if x.strip()] if head else []
            inner = s[brace + 1 : s.rfind("}")]
            for part in split_top(inner):
                go(prefix + segs, part)
            return
        m = re.match(r"(.*?)\s+as\s+(" + IDENT + r")$", s)
        alias = None
        if m:
            s, alias = m.group(1), m.group(2)
        segs = [x.strip() for x in s.split("::") if x.strip()]
        if segs and segs[-1] == "*":
            out.append((prefix + segs[:-1], "*"))
        elif segs and segs[-1] == "self":
            full = prefix + segs[:-1]
            if full:
                out.append((full, alias or full[-1]))
        elif segs:
            out.append((prefix + segs, alias or segs[-1]))

    go([], tree)
    return out


def split_top(s):
    parts, depth, cur = [], 0, []
    for ch in s:
        if ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
        if ch == "," and depth == 0:
            parts.append("".join(cur))
            cur = []
        else:
            cur.append(ch)
    parts.append("".join(cur))
    return parts


class Crate:
    def __init__(self, dir, root_file):
        self.dir = dir
        self.src = os.path.dirname(root_file)
        self.root = Module((), root_file, None)
        self.files = []
        self.load(self.root, root_file, is_root=True)

    def child_file(self, module, file, name, is_root):
        base = os.path.dirname(file)
        stem = os.path.splitext(os.path.basename(file))[0]
        if not (is_root or stem == "mod"):
            base = os.path.join(base, stem)
        base = os.path.join(base, *[m for m in module.inline_prefix]) if module.inline_prefix else base
        for cand in (os.path.join(base, name + ".rs"), os.path.join(base, name, "mod.rs")):
            if os.path.exists(cand):
                return cand
        return None

    def load(self, module, file, is_root=False):
        self.files.append(file)
        with open(file, encoding="utf-8") as f:
            text = strip(f.read())
        module.inline_prefix = []
        self.parse(module, file, text, is_root)

    def parse(self, top, file, text, is_root):
        # One pass: track braces to know which (inline) module each token is in, and the depth of
        # the module's own scope (items defined deeper are locals).
        stack = [(top, 0)]  # (module, brace depth of its scope)
        depth = 0
        i, n = 0, len(text)
        pending_mod = None
        token = re.compile(
            r"(?P<use>\b(?P<vis>pub(?:\s*\([^)]*\))?\s+)?use\s+(?P<tree>[^;]*);)"
            r"|(?P<mod>\bmod\s+(?P<mname>" + IDENT + r")\s*(?P<mend>[;{]))"
            r"|(?P<path>(?<![A-Za-z_0-9:])(?:" + IDENT + r")(?:\s*::\s*(?:" + IDENT + r"|\{))+)"
            r"|(?P<item>" + ITEM_RE.pattern + r")"
            r"|(?P<open>\{)|(?P<close>\})"
        )
        for m in token.finditer(text):
            line = text.count("\n", 0, m.start()) + 1
            module, scope = stack[-1]
            if m.group("open"):
                depth += 1
            elif m.group("close"):
                depth -= 1
                if len(stack) > 1 and depth < stack[-1][1]:
                    stack.pop()
            elif m.group("use"):
                public = bool(m.group("vis"))
                for segs, alias in flatten_use(m.group("tree")):
                    if alias == "*":
                        module.globs.append(segs)
                        if not public:
                            module.uses.append((segs, line))
                    else:
                        if depth == scope:
                            module.imports.setdefault(alias, segs)
                        if not public:
                            module.uses.append((segs, line))
            elif m.group("mod"):
                name = m.group("mname")
                if depth != scope:
                    continue
                if m.group("mend") == ";":
                    child_file = self.child_file(module, file, name, is_root)
                    if child_file is None:
                        continue
                    child = Module(module.path + (name,), child_file, module)
                    module.children[name] = child
                    self.load(child, child_file)
                else:
                    child = Module(module.path + (name,), file, module)
                    child.inline_prefix = module.inline_prefix + [name]
                    module.children[name] = child
                    depth += 1
                    stack.append((child, depth))
            elif m.group("item"):
                im = ITEM_RE.match(m.group("item"))
                name = im.group(1) or im.group(2)
                if depth == scope:
                    module.items.add(name)
            elif m.group("path"):
                p = re.sub(r"\s+", "", m.group("path"))
                segs = [s for s in p.split("::") if s]
                if segs[-1] == "{":
                    # `foo::{a, b}` in code is rare (only in `use`); keep the prefix.
                    segs = segs[:-1]
                if len(segs) >= 2:
                    module.uses.append((segs, line))

    # --- resolution ------------------------------------------------------------------------
    def resolve(self, module, segs, seen=None):
        """(module, whole): the module in which the path `segs`, named from `module`, is defined,
        and whether the path names that module itself; None if it leaves the crate."""
        seen = set() if seen is None else seen
        key = (module.path, tuple(segs))
        if key in seen:
            return None
        seen.add(key)
        cur = module
        for k, s in enumerate(segs):
            first = k == 0
            if s == "crate" and first:
                cur = self.root
            elif s == "super" and (first or segs[k - 1] == "super"):
                if cur.parent is None:
                    return None
                cur = cur.parent
            elif s == "self" and first:
                pass
            elif s in cur.children:
                cur = cur.children[s]
            elif s in cur.items:
                return cur, False
            elif s in cur.imports:
                hit = self.resolve(cur, cur.imports[s], seen)
                if hit is None:
                    return None
                target, whole = hit
                rest = segs[k + 1 :]
                if whole and rest:
                    return self.resolve(target, ["self"] + rest, seen)
                return target, whole and not rest
            else:
                for g in cur.globs:
                    hit = self.resolve(cur, g, seen)
                    if hit is None or not hit[1]:
                        continue
                    target = hit[0]
                    if s in target.items or s in target.children or s in target.imports:
                        return self.resolve(target, ["self"] + list(segs[k:]), seen)
                return None if first else (cur, False)
        return cur, True

    def modules(self):
        out, todo = [], [self.root]
        while todo:
            m = todo.pop()
            out.append(m)
            todo.extend(m.children.values())
        return out

    def edges(self):
        """{(file_a, file_b): set of names} for every use of file b by file a."""
        e = defaultdict(set)
        for m in self.modules():
            for segs, _line in m.uses:
                if segs[0] not in KEYWORDS and segs[0] not in m.imports and segs[0] not in m.children:
                    continue  # another crate, a local, `Self::…`, an enum variant …
                hit = self.resolve(m, segs)
                if hit is None or hit[0].file == m.file:
                    continue
                target = hit[0]
                e[(m.file, target.file)].add("::".join(segs))
        return e


def tarjan(nodes, adj):
    index, low, on, stack, out = {}, {}, set(), [], []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in adj.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            out.append(comp)

    sys.setrecursionlimit(10000)
    for v in nodes:
        if v not in index:
            visit(v)
    return out


def workspace_crates():
    with open(os.path.join(ROOT, "Cargo.toml"), encoding="utf-8") as f:
        toml = f.read()
    block = re.search(r"members\s*=\s*\[(.*?)\]", toml, re.S).group(1)
    members = re.findall(r'"([^"]+)"', block)
    return ["."] + members


def main(argv):
    dirs = argv[1:] or workspace_crates()
    bad = 0
    for d in dirs:
        crate_dir = os.path.join(ROOT, d)
        roots = [
            os.path.join(crate_dir, "src", f)
            for f in ("lib.rs", "main.rs")
            if os.path.exists(os.path.join(crate_dir, "src", f))
        ]
        if not roots:
            print(f"layering: {d}: no src/lib.rs or src/main.rs", file=sys.stderr)
            bad = 1
            continue
        for root_file in roots:
            crate = Crate(crate_dir, root_file)
            e = crate.edges()
            path_of = {}
            for m in crate.modules():
                path_of.setdefault(m.file, m.path)
            # The sibling graph at each module: child modules (each with its descendants) as
            # nodes, an edge when a file under one uses a file under another.
            graphs = defaultdict(lambda: defaultdict(set))
            why = defaultdict(list)
            for (a, b), names in e.items():
                pa, pb = path_of[a], path_of[b]
                k = 0
                while k < min(len(pa), len(pb)) and pa[k] == pb[k]:
                    k += 1
                if k == len(pa) or k == len(pb):
                    continue  # a module and its own submodules: one unit
                at, x, y = pa[:k], pa[k], pb[k]
                graphs[at][x].add(y)
                why[(at, x, y)].append((a, b, names))
            rel = lambda f: os.path.relpath(f, ROOT)
            name = os.path.relpath(root_file, ROOT)
            found = 0
            for at in sorted(graphs):
                adj = graphs[at]
                nodes = sorted(set(adj) | {y for ys in adj.values() for y in ys})
                for comp in tarjan(nodes, adj):
                    if len(comp) < 2:
                        continue
                    found += 1
                    where = "::".join(("crate",) + at)
                    print(f"{name}: IMPORT CYCLE between the modules {', '.join(sorted(comp))} of `{where}`:")
                    for x in sorted(comp):
                        for y in sorted(comp):
                            for a, b, names in why.get((at, x, y), ()):
                                ns = sorted(names)
                                more = f" (+{len(ns) - 6} more)" if len(ns) > 6 else ""
                                print(f"    {rel(a)} uses {rel(b)}: {', '.join(ns[:6])}{more}")
            if found:
                bad = 1
            else:
                files = len(set(crate.files))
                print(f"{name}: {files} files, {len(e)} file-to-file uses, no cycle between modules")
    if bad:
        print("layering: FAILED — break each cycle above (move the shared item into its own module "
              "below both files)", file=sys.stderr)
        return 1
    print("layering: no import cycles in any crate")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
