#!/usr/bin/env python3
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""Every GoogleTest test in Testing/ is in a leg's build, unless the leg's list says why not.

    check-suites.py LEG BUILD

Reads each TEST, TEST_F and TEST_P in Testing/**/*.cxx and fails when ctest -N in BUILD has
no test of that suite and name (after any INSTANTIATE_TEST_SUITE_P prefix, before any
parameter): a suite dropped by a CMake condition, a test compiled out, a file no longer
built. Testing/ci-legs.txt names, per leg, what may be absent and why ('absent' lines). It also
fails when a test the list says other legs cover ('covered' lines) matches no test in BUILD: a
stale line, left after a rename, would say a leg leaves to others what no longer exists."""

import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(Path(__file__).resolve().parent))
from ci_legs import allowed  # noqa: E402

DEFINITION = re.compile(r"^\s*TEST(?:_F|_P)?\(\s*(\w+)\s*,\s*(\w+)\s*\)", re.MULTILINE)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__.split("\n\n")[1])
    leg, build = sys.argv[1], sys.argv[2]
    listing = subprocess.run(["ctest", "--test-dir", build, "-N"], capture_output=True, text=True,
                             check=True).stdout
    names = set()
    full_names = []
    for line in listing.splitlines():
        match = re.match(r"\s*Test\s+#\d+: (\S+)", line)
        if match:
            name = match.group(1)
            full_names.append(name)
            if "/" in name and "." not in name.split("/")[0]:
                name = name.split("/", 1)[1]  # an INSTANTIATE_TEST_SUITE_P prefix
            names.add(name.split("/")[0])  # and its parameter
    absent = allowed(leg, "absent")
    missing = []
    defined = 0
    for source in sorted((ROOT / "Testing").rglob("*.cxx")):
        for suite, name in DEFINITION.findall(source.read_text(errors="replace")):
            defined += 1
            test = "%s.%s" % (suite, name)
            if test in names or any(pattern.fullmatch(test) for pattern, _ in absent):
                continue
            missing.append("%s (%s)" % (test, source.relative_to(ROOT)))
    covered = allowed(leg, "covered")
    left = [name for name in full_names if any(pattern.fullmatch(name) for pattern, _ in covered)]
    stale = [pattern.pattern for pattern, _ in covered
             if not any(pattern.fullmatch(name) for name in full_names)]
    print("suites (%s): %d tests defined in Testing/, %d missing from %s; %d of its %d tests left"
          " to the legs that run them against the same code (%d lines)"
          % (leg, defined, len(missing), build, len(left), len(full_names), len(covered)))
    if stale:
        print("check-suites: %s: 'covered' lines that match no test in %s:\n  %s"
              % (leg, build, "\n  ".join(stale)), file=sys.stderr)
        return 1
    if missing:
        print("check-suites: %s: tests that this leg's build should have and does not:\n  %s"
              % (leg, "\n  ".join(missing)), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
