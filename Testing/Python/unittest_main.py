# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""unittest's main for the suites that CTest runs: a suite in which any test skipped exits 77,
which CTest reports as skipped (SKIP_RETURN_CODE), so that a skip is never counted as a pass.
Each skip is printed with its reason; scripts/lib/check-skips.py then fails the leg unless
Testing/expected-skips.txt lists it. Failures and errors exit 1, as unittest's own main."""

import sys
import unittest


def main():
    program = unittest.main(module="__main__", exit=False, verbosity=2)
    result = program.result
    if not result.wasSuccessful():
        return 1
    for test, reason in result.skipped:
        print("SKIPPED %s: %s" % (test.id(), reason))
    return 77 if result.skipped else 0


if __name__ == "__main__":
    sys.exit("unittest_main.py is imported by the test suites, not run")
