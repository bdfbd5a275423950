#!/usr/bin/python3
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""What README.md and docs/*.md name in the repository exists.

    check-doc-paths.py [REPOSITORY]

- A `code span` or link target that starts with a top-level folder (Filters/, scripts/, ...):
  that file or folder (`a.{h,cxx}` is both; a name with no extension may be its .h or .cxx).
- A bare name of a class's file in a code span (`vtkBloomGallery.cxx`): a file of that name
  somewhere in the repository (other libraries' headers, such as vtk_glad.h, are not ours).
- "`Symbol` in `path`": the symbol appears in that file.
Exits 1, listing each missing name with its document and line.
"""
import os
import re
import subprocess
import sys

root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
# The repository's own folders: those git tracks (what a run writes, such as output/, is not
# a name the docs promise); without git, every folder but the build trees.
try:
    tracked = subprocess.run(["git", "-C", root, "ls-files"], capture_output=True, text=True,
                             check=True).stdout.split("\n")
    top_dirs = sorted({f.split("/")[0] for f in tracked if "/" in f})
except (OSError, subprocess.CalledProcessError):
    top_dirs = [e for e in os.listdir(root)
                if os.path.isdir(os.path.join(root, e)) and not e.startswith((".", "build"))]
names = set()
for folder, dirs, files in os.walk(root):
    dirs[:] = [d for d in dirs if not d.startswith((".", "build"))]
    names.update(files)
extensions = (".h", ".cxx", ".py", ".sh", ".cmake", ".glsl", ".xml", ".in", ".json")
span = re.compile(r"`([^`\s]+)`")
link = re.compile(r"\]\(([^)\s#]+)")
symbol_in = re.compile(r"`(\w+)` in `([^`\s]+)`")


def expand(name):
    match = re.search(r"\{([^{}]+)\}", name)
    if not match:
        return [name]
    return [n for part in match.group(1).split(",")
            for n in expand(name[: match.start()] + part + name[match.end():])]


def exists(path):
    return os.path.exists(path) or any(os.path.exists(path + e) for e in (".h", ".cxx"))


missing = []
documents = ["README.md"] + ["docs/" + f for f in sorted(os.listdir(os.path.join(root, "docs")))
                             if f.endswith(".md")]
for document in documents:
    base = os.path.dirname(os.path.join(root, document))
    with open(os.path.join(root, document), encoding="utf-8") as text:
        for number, line in enumerate(text, 1):
            where = "%s:%d: " % (document, number)
            for target in link.findall(line):
                if "://" not in target and not target.startswith("mailto:"):
                    if not os.path.exists(os.path.normpath(os.path.join(base, target))):
                        missing.append(where + target)
            for name in span.findall(line):
                name = name.rstrip(".,;:")
                if any(c in name for c in "*?<>$=…|()[]\\'\""):
                    continue
                for one in expand(name):
                    if one.split("/")[0] in top_dirs and "/" in one:
                        if not exists(os.path.join(root, one)):
                            missing.append(where + one)
                    elif re.match(r"^vtk[A-Z][\w.+-]*$", one) and one.endswith(extensions):
                        if one not in names:
                            missing.append(where + one)
            for symbol, path in symbol_in.findall(line):
                for one in expand(path):
                    full = os.path.join(root, one)
                    if os.path.isfile(full):
                        with open(full, encoding="utf-8", errors="replace") as f:
                            if symbol not in f.read():
                                missing.append(where + "%s in %s" % (symbol, one))
for entry in missing:
    print("missing:", entry)
print("%d documents, %d missing names" % (len(documents), len(missing)))
sys.exit(1 if missing else 0)
