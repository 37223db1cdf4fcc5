#!/usr/bin/env python3
"""Counts the lines of dispatch over the problems (issue 43, item 5), so that a change to the
dispatch can be measured before and after with the same rule.

Lines of dispatch, in every shipped `.rs` file of the core, the application and the Python crate
(unit-test modules excluded):
- the declaration of each erased trait (`trait Any...`) and each impl of one (`impl ... Any... for`);
- the adapter structs that carry a typed problem to its erased side (`struct ...Of<P>`, with
  their `impl ... ...Of<P>` blocks);
- the erased tables of a problem's faces (`pub struct ...Faces` / `impl ...Faces`);
- the typed dispatch: the visitor traits (`ForProblem`, `Visit`), their bounds (`Faces`,
  `Listed`) and their impls (a command body written as a visitor counts as an erased impl's does);
- the typed methods that hand a capability to the erased side (`fn continuum() -> Option<&...dyn`
  and the like: a problem's trait method returning `&'static dyn Any...`, or a fn pointer table);
- the callback macros `with_problems!` is expanded with (`macro_rules! NAME` where
  `with_problems!(NAME)` occurs).

Each item is counted as its lines of code: blank lines and `//` comment lines are not counted.
Also printed: the number of `with_problems!` expansions (shipped and in tests) and the number of
`pub` items of the core (`pub fn|struct|enum|trait|const|type|mod`, not `pub(crate)`).

Usage: python3 validation/dispatch_lines.py [ROOT] [-v]
"""

import os
import re
import sys

ROOT = next((a for a in sys.argv[1:] if not a.startswith("-")), ".")
VERBOSE = "-v" in sys.argv
DIRS = ["crates/microslip-core/src", "src", "python/src"]

STARTS = [
    ("erased trait", re.compile(r"^\s*(pub(\([a-z]+\))? )?trait Any\w+")),
    ("erased impl", re.compile(r"^\s*impl(<.*>)? Any\w+ for ")),
    ("adapter", re.compile(r"^\s*(pub(\([a-z]+\))? )?struct \w+Of<")),
    ("adapter", re.compile(r"^\s*impl(<.*>)? (\w+ for )?\w+Of<")),
    ("table", re.compile(r"^\s*pub(\([a-z]+\))? struct \w*Faces\b")),
    ("table", re.compile(r"^\s*impl(<.*>)? \w*Faces\b")),
    ("hand-out", re.compile(r"^\s*(pub )?fn \w+\(\)\s*->\s*(Option<)?&'static (\[&'static )?dyn Any")),
    ("hand-out", re.compile(r"^\s*(pub )?const FACES\b")),
    # The typed dispatch: the visitor traits a registry expansion runs (`ForProblem`, `Visit`),
    # their bounds (`Faces`, `Listed`), and every command body written as a visitor (counted like
    # an erased impl's bodies, so that moving a body from one to the other changes nothing).
    ("typed dispatch", re.compile(r"^\s*(pub(\([a-z]+\))? )?trait (ForProblem|Visit|Faces|Listed)\b")),
    ("typed dispatch", re.compile(r"^\s*impl(<.*>)? (ForProblem|Visit|Faces|Listed) for ")),
]


def shipped_lines(text):
    """The file's lines with `#[cfg(test)] mod` blocks blanked out."""
    lines = text.split("\n")
    out = list(lines)
    i = 0
    while i < len(lines):
        if lines[i].strip() == "#[cfg(test)]" and i + 1 < len(lines) and re.match(
            r"^\s*(pub(\(crate\))? )?mod \w+\s*\{", lines[i + 1]
        ):
            end = block_end(lines, i + 1)
            for j in range(i, end + 1):
                out[j] = ""
            i = end + 1
        else:
            i += 1
    return out


def block_end(lines, start):
    """The last line of the item starting at `start`: its matching brace, or its `;`."""
    depth = 0
    opened = False
    for j in range(start, len(lines)):
        code = lines[j].split("//")[0]
        for c in code:
            if c == "{":
                depth += 1
                opened = True
            elif c == "}":
                depth -= 1
        if opened and depth <= 0:
            return j
        if not opened and code.rstrip().endswith(";"):
            return j
    return len(lines) - 1


def is_code(line):
    s = line.strip()
    return s != "" and not s.startswith("//")


def main():
    files = []
    for d in DIRS:
        for dirpath, _, names in os.walk(os.path.join(ROOT, d)):
            files += [os.path.join(dirpath, n) for n in names if n.endswith(".rs")]
    files.sort()
    texts = {f: open(f, encoding="utf-8").read() for f in files}
    callbacks = set()
    expansions = 0
    for f, text in texts.items():
        for line in shipped_lines(text):
            if not is_code(line):
                continue
            for m in re.finditer(r"with_problems!\((\w+)\)", line):
                callbacks.add(m.group(1))
                expansions += 1
    starts = STARTS + [
        ("registry callback", re.compile(r"^\s*macro_rules!\s+(%s)\b" % "|".join(sorted(callbacks))))
    ]
    totals = {}
    per_file = {}
    for f, text in texts.items():
        lines = shipped_lines(text)
        counted = set()
        i = 0
        while i < len(lines):
            kind = next((k for k, rx in starts if rx.match(lines[i])), None)
            if kind is None:
                i += 1
                continue
            end = block_end(lines, i)
            n = sum(1 for j in range(i, end + 1) if j not in counted and is_code(lines[j]))
            counted.update(range(i, end + 1))
            totals[kind] = totals.get(kind, 0) + n
            rel = os.path.relpath(f, ROOT)
            per_file[rel] = per_file.get(rel, 0) + n
            if VERBOSE:
                print(f"  {rel}:{i + 1}-{end + 1} {kind} {n}: {lines[i].strip()[:70]}")
            i = end + 1
    tests_expansions = 0
    for f in [os.path.join(dp, n) for dp, _, ns in os.walk(os.path.join(ROOT, "tests")) for n in ns if n.endswith(".rs")]:
        tests_expansions += len(re.findall(r"with_problems!\((\w+)\)", open(f, encoding="utf-8").read()))
    pub_items = 0
    for f, text in texts.items():
        if "crates/microslip-core/src" in f:
            pub_items += len(re.findall(r"(?m)^\s*pub (fn|struct|enum|trait|const|type|mod) ", text))
    erased = sorted(
        {m.group(1) for t in texts.values() for m in re.finditer(r"(?m)^\s*(?:pub(?:\([a-z]+\))? )?trait (Any\w+)", t)}
    )
    print("lines of dispatch (code lines, shipped):", sum(totals.values()))
    for k in sorted(totals):
        print(f"  {k}: {totals[k]}")
    for crate in DIRS:
        print(f"  in {crate}: {sum(v for p, v in per_file.items() if p.startswith(crate + '/') and not (crate == 'src' and False))}")
    print("erased traits:", len(erased), " ".join(erased))
    print("with_problems! expansions: shipped", expansions, "+ tests/", tests_expansions)
    print("core pub items:", pub_items)


main()
