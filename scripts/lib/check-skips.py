#!/usr/bin/env python3
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""What a CI leg ran, checked against what it must run.

    check-skips.py LEG JUNIT.xml

JUNIT.xml is ctest's report (ctest --output-junit). Testing/ci-legs.txt lists, for each leg,
the tests it may skip and why ('skip' lines). The leg fails when a test skipped that its list does not
name (a compute test that found no compute shaders, a suite whose data went missing), or when
the report holds no test at all. A listed test that ran is reported, not failed: the list says
what a leg may lack, and a machine may have more. A test that the list says another leg covers
('covered' lines, which scripts/test.sh passes to ctest -E) fails the leg if it is in the
report: the leg ran what it says it leaves to others. It prints the leg's counts: tests run,
skipped (each with its reason) and failed."""

import re
import sys
import xml.etree.ElementTree as ElementTree
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from ci_legs import LIST, allowed  # noqa: E402


def outcomes(report):
    """Each test's name and outcome (run, skipped, failed) in ctest's JUnit report."""
    found = []
    for case in ElementTree.parse(report).getroot().iter("testcase"):
        status = case.get("status", "")
        if case.find("skipped") is not None or status in ("skipped", "disabled", "notrun"):
            found.append((case.get("name"), "skipped", (case.find("system-out").text or "")
                          if case.find("system-out") is not None else ""))
        elif case.find("failure") is not None or case.find("error") is not None or status == "fail":
            found.append((case.get("name"), "failed", ""))
        else:
            found.append((case.get("name"), "run", ""))
    return found


def said(output):
    """The reason a test gave for skipping, if any: the line after GoogleTest's "FILE:LINE:
    Skipped", or unittest_main.py's "SKIPPED ID: REASON"."""
    lines = output.splitlines()
    for number, line in enumerate(lines):
        if line.rstrip().endswith(": Skipped"):
            following = [text.strip() for text in lines[number + 1:number + 3] if text.strip()]
            if following and not following[0].startswith("["):
                return following[0][:160]
        match = re.match(r"SKIPPED (\S+): (.+)", line)
        if match:
            return match.group(2)[:160]
    return ""


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__.split("\n\n")[1])
    leg, report = sys.argv[1], sys.argv[2]
    permitted = allowed(leg, "skip")
    found = outcomes(report)
    counts = {kind: sum(1 for _, outcome, _ in found if outcome == kind) for kind in ("run", "skipped", "failed")}
    print("tests (%s): %d run, %d skipped, %d failed" % (leg, counts["run"], counts["skipped"], counts["failed"]))
    unlisted = []
    for name, outcome, output in found:
        if outcome != "skipped":
            continue
        reasons = [reason for pattern, reason in permitted if pattern.fullmatch(name)]
        if reasons:
            print("  skipped, as listed: %s (%s)" % (name, reasons[0]))
        else:
            unlisted.append(name)
            print("  SKIPPED, NOT LISTED: %s (%s)" % (name, said(output) or "no reason printed"))
    for pattern, reason in permitted:
        if not any(pattern.fullmatch(name) and outcome == "skipped" for name, outcome, _ in found):
            print("  listed, and ran here: %s (%s)" % (pattern.pattern, reason))
    covered = allowed(leg, "covered")
    stray = [name for name, _, _ in found if any(pattern.fullmatch(name) for pattern, _ in covered)]
    if stray:
        print("check-skips: %s: %d test(s) ran that %s leaves to other legs: %s"
              % (leg, len(stray), LIST.name, ", ".join(stray)), file=sys.stderr)
        return 1
    if not found:
        print("check-skips: %s: the report %s holds no test" % (leg, report), file=sys.stderr)
        return 1
    if unlisted:
        print("check-skips: %s: %d test(s) skipped that %s does not list for this leg: %s"
              % (leg, len(unlisted), LIST.name, ", ".join(unlisted)), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
