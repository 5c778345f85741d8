#!/usr/bin/env python3
"""Fails on a `#[test]` function that asserts nothing: a test that cannot fail.

Scans every `.rs` file of the workspace (`src/`, `tests/`, `benches/`, `crates/`; not
`target/`). A `#[test]` function passes if its body (comments and string literals removed)
holds one of:

- an assertion macro: `assert!`, `assert_eq!`, `assert_ne!`, `prop_assert!`,
  `prop_assert_eq!`, `prop_assert_ne!`, `assert_matches!` (`debug_assert*` do not count:
  they vanish in the release profile the tests run in);
- an explicit failure: `panic!`, `unreachable!`, `unimplemented!`, `todo!`, `bail!`
  (under a condition, that is a check);
- `.unwrap_err()` / `.expect_err(` (the call must fail);
- a call to a helper function that passes by these rules (helpers defined in the same file
  or in a `common` module beside it, followed transitively);

or if it is marked `#[should_panic]`. NOT counted on their own: `.unwrap()` and `.expect(`
(they are everywhere in setup code, so counting them would pass every test), and `?` in a
test returning `Result`. A test whose whole check is that a call returns `Ok` says so with
`assert!(x.is_ok(), ...)` or by matching the result.

A test that still has a reason to assert nothing goes into ALLOWED below, with the reason.

    python3 tools/check-tests-assert.py        # from the repository root; exit 1 on offenders
"""

import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

# "path::test_name": why it may assert nothing.
ALLOWED = {}

ASSERTS = re.compile(
    r"\b(assert|assert_eq|assert_ne|prop_assert|prop_assert_eq|prop_assert_ne|assert_matches"
    r"|panic|unreachable|unimplemented|todo|bail)!"
    r"|\.unwrap_err\(\)|\.expect_err\("
)
FN = re.compile(r"\bfn\s+([A-Za-z_][A-Za-z0-9_]*)")


def strip(text):
    """The source with comments, string and char literals blanked (lengths kept)."""
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
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == "r" and re.match(r'r#*"', text[i:]) and not re.match(r"\w", text[i - 1 : i]):
            hashes = re.match(r"r(#*)\"", text[i:]).group(1)
            end = '"' + hashes
            j = text.find(end, i + 2 + len(hashes))
            j = n if j < 0 else j + len(end)
            out.append('""' + re.sub(r"[^\n]", " ", text[i + 2 : j]))
            i = j
        elif c == '"':
            j = i + 1
            while j < n and text[j] != '"':
                j += 2 if text[j] == "\\" else 1
            out.append('"' + re.sub(r"[^\n]", " ", text[i + 1 : j]) + '"')
            i = j + 1
        elif c == "'" and re.match(r"'(\\.|[^\\'])'", text[i:]):
            m = re.match(r"'(\\.|[^\\'])'", text[i:])
            out.append("' '")
            out.append(" " * (len(m.group(0)) - 3))
            i += len(m.group(0))
        else:
            out.append(c)
            i += 1
    return "".join(out)


def functions(text):
    """(name, start of `fn`, body) of every function with a body in stripped `text`."""
    out = []
    for m in FN.finditer(text):
        i = m.end()
        # The parameter list, then the body's opening brace (a `;` first: no body).
        depth, j = 0, i
        while j < len(text):
            ch = text[j]
            if ch in "([<":
                depth += 1
            elif ch in ")]>" and not (ch == ">" and text[j - 1] == "-"):
                depth -= 1
            elif ch == ";" and depth <= 0:
                j = -1
                break
            elif ch == "{" and depth <= 0:
                break
            j += 1
        if j < 0 or j >= len(text):
            continue
        depth, k = 0, j
        while k < len(text):
            if text[k] == "{":
                depth += 1
            elif text[k] == "}":
                depth -= 1
                if depth == 0:
                    break
            k += 1
        out.append((m.group(1), m.start(), text[j : k + 1]))
    return out


def attributes_before(text, pos):
    """The attributes just above the `fn` at `pos`."""
    head = text[:pos]
    attrs = []
    for line in reversed(head.splitlines()):
        s = line.strip()
        if not s or s.startswith("#[") or s in ("pub", "async") or s.startswith("pub("):
            if s.startswith("#["):
                attrs.append(s)
            continue
        break
    # Attributes on the fn's own line (`#[test] fn x()`).
    line_start = head.rfind("\n") + 1
    attrs += re.findall(r"#\[[^\]]*\]", head[line_start:])
    return attrs


def helpers_of(path):
    """The files whose functions a test in `path` may call: itself and `common` beside it."""
    files = [path]
    common = path.parent / "common"
    if common.is_dir():
        files += sorted(common.rglob("*.rs"))
    elif (path.parent / "common.rs").is_file():
        files.append(path.parent / "common.rs")
    return files


def main():
    sources = {}
    for top in ("src", "tests", "benches", "crates"):
        for p in sorted((ROOT / top).rglob("*.rs")):
            if "target" in p.relative_to(ROOT).parts:
                continue
            sources[p] = strip(p.read_text())
    parsed = {p: functions(t) for p, t in sources.items()}
    offenders = []
    tests = 0
    for path, text in sources.items():
        if "#[test]" not in text:
            continue
        # Which helper names assert, to a fixed point.
        bodies = {}
        for f in helpers_of(path):
            for name, _, body in parsed.get(f, []):
                bodies.setdefault(name, []).append(body)
        asserting = {n for n, bs in bodies.items() if any(ASSERTS.search(b) for b in bs)}
        changed = True
        while changed:
            changed = False
            for n, bs in bodies.items():
                if n in asserting:
                    continue
                if any(re.search(r"\b(" + "|".join(map(re.escape, asserting)) + r")\s*(::<[^>]*>)?\(", b)
                       for b in bs) if asserting else False:
                    asserting.add(n)
                    changed = True
        for name, pos, body in parsed[path]:
            attrs = attributes_before(text, pos)
            if not any(a.startswith("#[test]") for a in attrs):
                continue
            tests += 1
            if any(a.startswith("#[should_panic") for a in attrs):
                continue
            if ASSERTS.search(body):
                continue
            calls = set(re.findall(r"\b([A-Za-z_][A-Za-z0-9_]*)\s*(?:::<[^>]*>)?\(", body))
            if calls & (asserting - {name}):
                continue
            key = f"{path.relative_to(ROOT)}::{name}"
            if key in ALLOWED:
                continue
            line = text.count("\n", 0, pos) + 1
            offenders.append(f"{path.relative_to(ROOT)}:{line}: {name}")
    if offenders:
        print(f"{len(offenders)} of {tests} tests assert nothing (see tools/check-tests-assert.py):")
        print("\n".join(offenders))
        sys.exit(1)
    print(f"{tests} tests, each with an assertion")


if __name__ == "__main__":
    main()
