#!/usr/bin/env python3
"""Every citation of a benchmarks section names one that exists, and the front page's index
lists every section of the history.

The code's comments and the docs cite measurements by the file (benchmark-history.md or
benchmarks.md) and the section's title in double quotes. This finds each such citation in the
tracked files and checks that the cited file has a heading or a bold paragraph lead starting
with that title. Titles may wrap onto the next comment line; the part before the break is
checked.
Usage: doc_references_test.py REPO_ROOT
"""
import pathlib
import re
import subprocess
import sys

root = pathlib.Path(sys.argv[1])
files = subprocess.run(["git", "-C", str(root), "ls-files"], capture_output=True, text=True,
                       check=True).stdout.split()
docs = {name: (root / "docs" / name).read_text() for name in ("benchmarks.md", "benchmark-history.md")}


def titles(text):
    found = [line.lstrip("#").strip() for line in text.splitlines() if line.startswith("#")]
    found += re.findall(r"\*\*([^*]+)\*\*", text)
    return [re.sub(r"\s+", " ", t) for t in found]


known = {name: titles(text) for name, text in docs.items()}
citation = re.compile(r"(benchmarks|benchmark-history)\.md[`\])(a-z/._,:;\s-]{0,40}?\"([A-Za-z][^\"\n]{2,})")
errors = []
for name in files:
    path = root / name
    if path.suffix not in {".cc", ".h", ".md", ".sh", ".py", ".yaml", ".txt", ".cmake"}:
        continue
    text = path.read_text(errors="replace")
    # A comment's line break inside a citation is a space.
    flat = re.sub(r"\n\s*(//|#|\*)?\s*", " ", text)
    for match in citation.finditer(flat):
        cited = match.group(2).strip().rstrip(",.;:)")
        if len(cited) < 3 or cited.startswith("A glance"):
            continue
        target = match.group(1) + ".md"
        if not any(t.startswith(cited) or cited.startswith(t) for t in known[target]):
            errors.append(f"{name}: cites {target}, \"{cited}\": no such section")
# The front page's index lists every section of the history.
index = docs["benchmarks.md"].split("## The history's sections", 1)[-1]
for line in docs["benchmark-history.md"].splitlines():
    if line.startswith("### ") and f"- {line[4:]}" not in index:
        errors.append(f"benchmarks.md: the history's section \"{line[4:]}\" is not in its index")
for error in errors:
    print(error)
print(f"{len(errors)} citation(s) of a missing section or section(s) missing from the index")
sys.exit(1 if errors else 0)
