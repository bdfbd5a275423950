# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""The long sessions' memory (imported by bloom_view_soak.py, bloom_catalyst_soak.py and
run_tests.py, not run): a process's resident size, and a session's growth from its samples."""


def resident_kib():
    """This process's resident memory (VmRSS), in KiB."""
    with open('/proc/self/status') as status:
        for line in status:
            if line.startswith('VmRSS:'):
                return int(line.split()[1])
    return 0


def growth(samples):
    """The smallest of the last sixth of `samples` minus the largest of the first sixth (at
    least 3 each): growth that the allocator's fluctuation does not make."""
    k = max(3, len(samples) // 6)
    return min(samples[-k:]) - max(samples[:k])
