#!/usr/bin/env python3
"""List the import circles between the modules of each crate (`crates/*/src`).

What it counts, exactly:

- A *module* is a source file under a crate's `src/` (`a/b.rs` and `a/b/mod.rs` are module
  `a::b`; `lib.rs` and `main.rs` are the crate root), or a `mod x { ... }` written at the top
  level of such a file (its own module, whose insides are not read: in osc2cr, generated types
  and `include!`s). Comments and code after the file's first `#[cfg(test)]` (unit tests) are not
  read.
- Module A *uses* module B when A names a path into B: in a `use` item or in a qualified path in
  code (`crate::b::f()`, `super::b::T`, `self::c::T`). A path is followed segment by segment: a
  child module descends, an item name stops at the module that defines it, and a name the module
  only re-exports (`pub use x::T`, `pub use x::*`) is followed to where it is defined, so that
  naming `crate::Error` is a use of the module that defines `Error`, not of the crate root.
  `mod x;` declarations and uses of other crates are not uses.
- An *import circle* is a strongly connected set of two or more modules of one crate in that
  graph (each can reach every other through uses). The script prints each circle with the uses
  that close it, and the number of circles per crate and in all.

    tools/module_cycles.py [WORKSPACE]      # default: the folder above tools/
"""
import re
import sys
from pathlib import Path

DEF = re.compile(
    r"^\s*(?:pub(?:\([^)]*\))?\s+)?(?:unsafe\s+|async\s+|const\s+|extern\s+\"C\"\s+)*"
    r"(?:fn|struct|enum|trait|type|const|static|union|macro_rules!)\s+([A-Za-z_]\w*)",
    re.M,
)
MACRO_EXPORT = re.compile(r"macro_rules!\s+([A-Za-z_]\w*)")
INLINE_MOD = re.compile(r"^(?:pub(?:\([^)]*\))?\s+)?mod\s+([A-Za-z_]\w*)\s*\{", re.M)
USE = re.compile(r"\b(pub(?:\([^)]*\))?\s+)?use\s+([^;]+);", re.S)
PATH = re.compile(r"(?<![\w:])((?:crate|super|self)(?:::[A-Za-z_]\w*)+)")


def module_files(src: Path) -> dict:
    """Module path (tuple of names) -> file."""
    out = {}
    for f in sorted(src.rglob("*.rs")):
        rel = f.relative_to(src).with_suffix("")
        parts = list(rel.parts)
        if parts in (["lib"], ["main"]):
            parts = []
        elif parts[-1] == "mod":
            parts = parts[:-1]
        elif len(parts) >= 2 and parts[0] == "bin":
            continue  # a separate crate root
        out[tuple(parts)] = f
    return out


def without_tests_and_comments(text: str) -> str:
    text = re.sub(r"//[^\n]*", "", text)
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    cut = re.search(r"#\[cfg\(test\)\]", text)
    return text[: cut.start()] if cut else text


def expand_use(tree: str) -> list:
    """`a::{b, c::{d as e}}` -> ['a::b', 'a::c::d@e']: one path per name (`@` marks an alias)."""
    tree = re.sub(r"\s+", "", re.sub(r"\s+as\s+", "@", tree))
    m = re.match(r"^(.*?)\{(.*)\}$", tree)
    if not m:
        return [tree]
    prefix, inner = m.group(1), m.group(2)
    parts, depth, cur = [], 0, ""
    for ch in inner:
        if ch == "," and depth == 0:
            parts.append(cur)
            cur = ""
            continue
        depth += ch == "{"
        depth -= ch == "}"
        cur += ch
    parts.append(cur)
    out = []
    for p in parts:
        if p:
            out.extend(prefix + q for q in expand_use(p))
    return out


class Crate:
    def __init__(self, src: Path):
        self.src = src
        self.files = module_files(src)
        self.text = {m: without_tests_and_comments(f.read_text(encoding="utf-8")) for m, f in self.files.items()}
        self.defs = {m: set(DEF.findall(t)) | set(MACRO_EXPORT.findall(t)) for m, t in self.text.items()}
        # an inline `mod x { ... }` is a module of its own (the items inside are not read)
        for m, t in list(self.text.items()):
            for inline in INLINE_MOD.findall(t):
                self.files.setdefault(m + (inline,), self.files[m])
                self.text.setdefault(m + (inline,), "")
                self.defs.setdefault(m + (inline,), set())
        # re-exports: module -> {name: absolute path}, and glob sources
        self.reexports = {m: {} for m in self.files}
        self.globs = {m: [] for m in self.files}
        for m, t in self.text.items():
            for vis, tree in USE.findall(t):
                if not vis:
                    continue
                for p in expand_use(tree):
                    p, _, alias = p.partition("@")
                    name = alias or p.split("::")[-1]
                    absolute = self.absolute(m, p.split("::"))
                    if absolute is None:
                        continue
                    if absolute[-1] == "*":
                        self.globs[m].append(tuple(absolute[:-1]))
                    else:
                        self.reexports[m][name] = absolute

    def absolute(self, here, segs):
        """Segments of a path as written in module `here`, made absolute (from the crate root);
        None for a path into another crate."""
        segs = [s for s in segs if s]
        if not segs:
            return None
        if segs[0] == "crate":
            return list(segs[1:])
        if segs[0] in ("self", "super"):
            base = list(here)
            while segs and segs[0] in ("self", "super"):
                if segs[0] == "super":
                    base = base[:-1]
                segs = segs[1:]
            return base + segs
        # a relative path: a child module of `here`
        if tuple(here) + (segs[0],) in self.files:
            return list(here) + segs
        return None

    def target(self, segs, seen=None):
        """The module that defines what the absolute path `segs` names."""
        seen = seen or set()
        key = tuple(segs)
        if key in seen:
            return None
        seen.add(key)
        mod = ()
        for i, s in enumerate(segs):
            if s in ("*", "self"):
                return mod
            if mod + (s,) in self.files:
                mod = mod + (s,)
                continue
            if s in self.defs.get(mod, ()):
                return mod
            if s in self.reexports.get(mod, {}):
                return self.target(self.reexports[mod][s] + list(segs[i + 1:]), seen)
            for g in self.globs.get(mod, []):
                t = self.target(list(g) + [s] + list(segs[i + 1:]), seen)
                if t is not None:
                    return t
            return mod
        return mod

    def edges(self):
        out = {}
        for m, t in self.text.items():
            paths = []
            for _, tree in USE.findall(t):
                paths.extend(expand_use(tree))
            body = USE.sub("", t)
            paths.extend(PATH.findall(body))
            for p in paths:
                p = p.partition("@")[0]
                a = self.absolute(m, p.split("::"))
                if a is None:
                    continue
                target = self.target(a)
                if target is not None and target != m:
                    out.setdefault(m, {}).setdefault(target, p)
        return out


def circles(edges: dict) -> list:
    """Strongly connected components of two or more nodes (Tarjan)."""
    index, low, stack, on, out = {}, {}, [], set(), []
    counter = [0]
    nodes = set(edges) | {t for ts in edges.values() for t in ts}

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in edges.get(v, {}):
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
            if len(comp) > 1:
                out.append(sorted(comp))

    sys.setrecursionlimit(10000)
    for v in sorted(nodes):
        if v not in index:
            visit(v)
    return sorted(out)


def name(m) -> str:
    return "::".join(m) or "crate"


def main() -> None:
    root = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parent.parent
    total = 0
    for src in sorted(root.glob("crates/*/src")):
        crate = Crate(src)
        edges = crate.edges()
        found = circles(edges)
        total += len(found)
        for comp in found:
            members = set(comp)
            print(f"{src.parent.name}: {{{', '.join(name(m) for m in comp)}}}")
            for a in comp:
                for b, via in sorted(edges.get(a, {}).items()):
                    if b in members:
                        print(f"    {name(a)} -> {name(b)}  ({via})")
    print(f"{total} import circles")


if __name__ == "__main__":
    main()
