#!/usr/bin/env python3
"""Docs that cannot rot: run by ctest (tests/docs/CMakeLists.txt) from the repository root.

1. A fenced code block right after a line `<!-- file: PATH -->` must be exactly the file PATH
   (repository-relative), which the test suite builds and runs: examples/plugin-vsm is built
   out of tree by plugin_example_out_of_tree, so the recipes in docs/ are the tested ones.
2. Every relative Markdown link in README.md and docs/ points at a file or folder inside the
   repository: no page cites a document that is not in it.
Prints every problem as FILE:LINE: message and exits 1 when there is one.
"""
import os
import re
import sys

root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else ".")
pages = [os.path.join(root, "README.md")]
for d, _, files in os.walk(os.path.join(root, "docs")):
    pages += [os.path.join(d, f) for f in sorted(files) if f.endswith(".md")]

problems = []
link = re.compile(r"\[[^\]]*\]\(([^)\s]+)\)")
for page in pages:
    rel_page = os.path.relpath(page, root)
    lines = open(page, encoding="utf-8").read().split("\n")
    i = 0
    while i < len(lines):
        m = re.match(r"<!-- file: (\S+) -->\s*$", lines[i])
        if m:
            path = os.path.join(root, m.group(1))
            if i + 1 >= len(lines) or not lines[i + 1].startswith("```"):
                problems.append(f"{rel_page}:{i + 1}: no code block after the file marker")
            else:
                end = i + 2
                while end < len(lines) and lines[end] != "```":
                    end += 1
                block = "\n".join(lines[i + 2:end]) + "\n"
                if not os.path.isfile(path):
                    problems.append(f"{rel_page}:{i + 1}: {m.group(1)} does not exist")
                elif open(path, encoding="utf-8").read() != block:
                    problems.append(f"{rel_page}:{i + 1}: the block differs from {m.group(1)}; copy the file in")
                i = end
        for target in link.findall(lines[i]) if i < len(lines) else []:
            if re.match(r"^[a-z]+:", target) or target.startswith("#"):
                continue  # a URL or an anchor on the same page
            target_path = os.path.normpath(os.path.join(os.path.dirname(page), target.split("#")[0]))
            if os.path.relpath(target_path, root).startswith(".."):
                problems.append(f"{rel_page}:{i + 1}: link {target} leaves the repository")
            elif not os.path.exists(target_path):
                problems.append(f"{rel_page}:{i + 1}: link {target} points at nothing")
        i += 1

for p in problems:
    print(p)
print(f"{len(pages)} pages checked, {len(problems)} problems")
sys.exit(1 if problems else 0)
