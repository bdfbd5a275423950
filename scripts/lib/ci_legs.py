# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""Testing/ci-legs.txt, read by check-skips.py and check-suites.py: for each CI leg, the tests
it may skip and the tests it may lack, each with its reason."""

import re
import sys
from pathlib import Path

LIST = Path(__file__).resolve().parents[2] / "Testing" / "ci-legs.txt"
LEGS = {"x11", "osmesa", "egl", "sid", "sid-x", "asan"}


def allowed(leg, kind):
    """The (compiled ctest-name pattern, reason) pairs of `kind` ('skip' or 'absent') for LEG,
    from lines 'LEGS KIND PATTERN -- REASON' (LEGS: comma-separated, or *)."""
    if leg not in LEGS:
        sys.exit("ci_legs: no leg %r (legs: %s)" % (leg, ", ".join(sorted(LEGS))))
    found = []
    for number, line in enumerate(LIST.read_text().splitlines(), 1):
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        match = re.fullmatch(r"(\S+)\s+(skip|absent)\s+(\S+)\s+--\s+(\S.*)", line)
        legs = match.group(1).split(",") if match else []
        if not match or not (legs == ["*"] or set(legs) <= LEGS):
            sys.exit("ci_legs: %s:%d: expected 'LEGS skip|absent PATTERN -- REASON', LEGS from %s"
                     % (LIST, number, ", ".join(sorted(LEGS))))
        if match.group(2) == kind and (legs == ["*"] or leg in legs):
            found.append((re.compile(match.group(3)), match.group(4)))
    return found
