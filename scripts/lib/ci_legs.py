# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""Testing/ci-legs.txt, read by check-skips.py, check-suites.py and scripts/test.sh: for each
CI leg, the tests it may skip, the tests it may lack, and the tests it leaves to the legs that
run them against the same code, each with its reason.

    ci_legs.py exclude LEG     prints the ctest -E expression of LEG's 'covered' tests (empty
                               when it has none)

A 'covered' line may name only the legs that repeat another's work (osmesa, egl, sid-x, asan):
x11 runs every test against VTK 9.1 and sid every test against VTK 9.6. Its patterns are
written in the regular expressions CMake and Python share (no backslash, no braces, no '(?')."""

import re
import sys
from pathlib import Path

LIST = Path(__file__).resolve().parents[2] / "Testing" / "ci-legs.txt"
LEGS = {"x11", "osmesa", "egl", "sid", "sid-x", "asan"}
COMPLETE_LEGS = {"x11", "sid"}  # the legs that run every test: never 'covered'
KINDS = ("skip", "absent", "covered")


def entries():
    """Each line of the list as (legs, kind, pattern, reason); legs is a set, or {'*'}."""
    found = []
    for number, line in enumerate(LIST.read_text().splitlines(), 1):
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        match = re.fullmatch(r"(\S+)\s+(%s)\s+(\S+)\s+--\s+(\S.*)" % "|".join(KINDS), line)
        legs = set(match.group(1).split(",")) if match else set()
        where = "ci_legs: %s:%d: " % (LIST, number)
        if not match or not (legs == {"*"} or legs <= LEGS):
            sys.exit(where + "expected 'LEGS %s PATTERN -- REASON', LEGS from %s"
                     % ("|".join(KINDS), ", ".join(sorted(LEGS))))
        kind, pattern = match.group(2), match.group(3)
        if kind == "covered" and (legs == {"*"} or legs & COMPLETE_LEGS):
            sys.exit(where + "x11 and sid run every test: a 'covered' line may not name them")
        if kind == "covered" and re.search(r"\\|\{|\(\?", pattern):
            sys.exit(where + "a 'covered' pattern is also ctest's: no backslash, brace or '(?'")
        found.append((legs, kind, pattern, match.group(4)))
    return found


def allowed(leg, kind):
    """The (compiled ctest-name pattern, reason) pairs of `kind` for LEG."""
    if leg not in LEGS:
        sys.exit("ci_legs: no leg %r (legs: %s)" % (leg, ", ".join(sorted(LEGS))))
    return [(re.compile(pattern), reason) for legs, line_kind, pattern, reason in entries()
            if line_kind == kind and (legs == {"*"} or leg in legs)]


def exclusion(leg):
    """ctest's -E expression for LEG's 'covered' tests: each pattern matched whole."""
    patterns = [pattern.pattern for pattern, _ in allowed(leg, "covered")]
    return "^(%s)$" % "|".join(patterns) if patterns else ""


if __name__ == "__main__":
    if len(sys.argv) != 3 or sys.argv[1] != "exclude":
        sys.exit(__doc__.split("\n\n")[1])
    print(exclusion(sys.argv[2]))
