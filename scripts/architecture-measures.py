#!/usr/bin/python3
"""The measures of issue 63 (one engine, one traversal, one way to render), on the product's code.

  scripts/architecture-measures.py [--functions N]

Run from the repository root. Product code is every .cpp and .hpp under the
library folders and cli/ (not tests/, bench/, fuzz/, build folders). Each
measure is defined here, so that a before and an after are comparable:
- long functions: a definition that starts at column 0 and ends at the
  next line that is a lone '}' at column 0 (the code's style: namespace
  bodies are not indented; in-class members are not counted); its length is
  the lines from signature to closing brace; counted over 60 and over 100,
  the N longest listed with --functions N;
- application entry points: functions declared public in rewriting/*.hpp
  (not detail/) whose name is apply, apply_*, rewrite_*, derive or
  match_scheme, and classes named *Rewriter or *Applier;
- union-find copies: files with a parent-table loop `while (t[x] != x)`;
- one-dart-per-orbit loops: lines `if (seen[d]) continue;` (any array named
  seen, visited, marked or done) in a loop over darts;
- format comparisons outside cli/: string comparisons with "text", "json",
  "jsonl", "sarif", "junit" or "github";
- `InputError("<command line>"` outside cli/;
- cli/ lines.
"""
import glob
import re
import sys

FOLDERS = ["analysis", "campaign", "checkers", "cli", "compiler", "core", "events", "generators", "inference", "io", "proofs", "querymodify",
           "reports", "rewriting"]


def product_files():
    out = []
    for folder in FOLDERS:
        out += sorted(glob.glob(f"{folder}/**/*.cpp", recursive=True) + glob.glob(f"{folder}/**/*.hpp", recursive=True))
    return out


def functions(path, lines):
    """(length, path:line, signature) of each column-0 definition."""
    out = []
    i = 0
    skip = re.compile(r"^(#|//|namespace|}|using |template ?<[^>]*>$|struct |class |enum |union |extern |static_assert|\s|$)")
    while i < len(lines):
        line = lines[i]
        if skip.match(line) or line.rstrip().endswith(";"):
            i += 1
            continue
        # The signature runs to the first line ending in '{' before any ';'.
        j = i
        while j < len(lines) and not lines[j].rstrip().endswith(("{", ";", "}")):
            j += 1
        if j >= len(lines) or not lines[j].rstrip().endswith("{") or "=" in lines[i].split("(")[0]:
            i = j + 1  # a declaration, a one-line definition, a variable
            continue
        k = j + 1
        while k < len(lines) and not lines[k].startswith("}"):
            k += 1
        if k < len(lines) and "(" in "".join(lines[i:j + 1]):
            out.append((k - i + 1, f"{path}:{i + 1}", lines[i].strip()[:100]))
        i = k + 1
    return out


def main():
    top = int(sys.argv[sys.argv.index("--functions") + 1]) if "--functions" in sys.argv else 0
    files = product_files()
    text = {p: open(p, encoding="utf-8").read() for p in files}
    all_functions = []
    for p in files:
        if p.endswith(".cpp"):
            all_functions += functions(p, text[p].split("\n"))
    all_functions.sort(reverse=True)
    over60 = sum(1 for f in all_functions if f[0] > 60)
    over100 = sum(1 for f in all_functions if f[0] > 100)
    print(f"product functions over 60 lines: {over60}, over 100: {over100}, longest {all_functions[0][0]} ({all_functions[0][1]})")
    for length, where, signature in all_functions[:top]:
        print(f"  {length:4} {where}  {signature}")

    entry = re.compile(r"^[A-Za-z][^;(]*\b(apply|apply_\w+|rewrite_\w+|derive|match_scheme)\(", re.M)
    rewriters = re.compile(r"^class (\w*(?:Rewriter|Applier))\b(?!;)", re.M)  # a definition, not a declaration
    points = []
    for p in files:
        if p.startswith("rewriting/") and p.endswith(".hpp") and "/detail/" not in p:
            points += [f"{p}: {m.group(1)}" for m in entry.finditer(text[p])]
            points += [f"{p}: class {m.group(1)}" for m in rewriters.finditer(text[p])]
    print(f"public application entry points in rewriting/: {len(points)}")
    for x in points:
        print(f"  {x}")

    uf = [p for p in files if re.search(r"while \((\w+)\[(?:static_cast<[^>]*>\()?(\w+)\)?\] != \2\)", text[p])]
    print(f"union-find copies (files): {len(uf)}: {' '.join(uf)}")
    seen = [(p, n) for p in files for n in [len(re.findall(r"if \((?:seen|visited|marked|done)\[\w+\]\) continue;", text[p]))] if n]
    print(f"one-dart-per-orbit loops with a mark array: {sum(n for _, n in seen)} in {len(seen)} files: {' '.join(p for p, _ in seen)}")
    fmt = [(p, n) for p in files if not p.startswith("cli/")
           for n in [len(re.findall(r'==\s*"(?:text|json|jsonl|sarif|junit|github)"|"(?:text|json|jsonl|sarif|junit|github)"\s*==', text[p]))] if n]
    print(f"format string comparisons outside cli/: {sum(n for _, n in fmt)} in {len(fmt)} files")
    cl = [(p, text[p].count('InputError("<command line>"')) for p in files if not p.startswith("cli/")]
    cl = [(p, n) for p, n in cl if n]
    print(f'InputError("<command line>") outside cli/: {sum(n for _, n in cl)} in {len(cl)} files')
    cli_lines = sum(text[p].count("\n") for p in files if p.startswith("cli/"))
    print(f"cli/ lines: {cli_lines}")


main()
