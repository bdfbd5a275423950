# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""Tables and checks from the GPU runs of scripts/paraview-gpu-run.sh (Markdown on stdout).

    python3 bloom_gpu_report.py devices ONE_RANK_DIR N_RANK_DIR [REFERENCE_DIR]
    python3 bloom_gpu_report.py bench BENCH.jsonl [MORE.jsonl ...]
    python3 bloom_gpu_report.py compare A.png B.png

devices: each rank of the N-rank run of bloom_gpu_devices.py (its device-RANK.json: the EGL
device index, CUDA device and GPU UUID its own context reported) beside what the driver says:
nvidia-smi's process list taken while the ranks held their contexts (nvidia-smi.txt), matched by
process id, and the card's index by UUID (gpus.csv). Checks, each a PASS or FAIL line: every
rank renders on NVIDIA's EGL; ranks on distinct GPUs where there are as many GPUs as ranks; each
rank's process listed by nvidia-smi on the GPU its context names; the N-rank image equals the
1-rank one (and REFERENCE_DIR's hdr-400-300.png, the one-GPU machine's) within one level and
1e-3 relative L2 (run_tests.py's bound for the float composite). The exit status counts FAILs.

bench: the records of bloom_gpu_timing.py as one table (frame time mean, p99, max; IceT's
render, composite and collect time and bytes sent on rank 0; the bloom's GPU time), then the
64-rank projection from the bytes IceT sent (see docs/paraview.md, On GPU nodes).

compare: max level difference and relative L2 of two PNGs of the same size.
"""
import csv
import glob
import json
import os
import re
import sys

failures = 0


def check(ok, what):
    global failures
    print(('PASS ' if ok else 'FAIL ') + what)
    failures += 0 if ok else 1


def load_png(path):
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    w, h, _ = reader.GetOutput().GetDimensions()
    return vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars()).astype(float).reshape(h, w, -1)


def compare(a_path, b_path):
    import numpy as np
    a, b = load_png(a_path), load_png(b_path)
    if a.shape != b.shape:
        return None, None
    worst = float(np.abs(a - b).max())
    l2 = float(np.linalg.norm(a - b) / max(np.linalg.norm(b), 1e-300))
    return worst, l2


def smi_processes(path):
    """nvidia-smi's process table: {pid: [(gpu index, type, name, memory)]}."""
    rows = {}
    if not os.path.exists(path):
        return rows
    pattern = re.compile(r'^\|\s+(\d+)\s+\S+\s+\S+\s+(\d+)\s+(C\+G|C|G|M\+C|M)\s+(\S+).*?(\d+MiB|N/A)\s*\|')
    for line in open(path, errors='replace'):
        m = pattern.match(line)
        if m:
            rows.setdefault(int(m.group(2)), []).append(
                (int(m.group(1)), m.group(3), os.path.basename(m.group(4)), m.group(5)))
    return rows


def smi_gpus(path):
    """nvidia-smi's index of each GPU UUID."""
    gpus = {}
    if os.path.exists(path):
        for row in csv.reader(open(path)):
            if len(row) >= 2 and row[0].strip().isdigit():
                gpus[row[1].strip()] = int(row[0])
    return gpus


def devices(one, many, reference=None):
    records = [json.load(open(p)) for p in sorted(glob.glob(os.path.join(many, 'device-*.json')))]
    records.sort(key=lambda r: r['rank'])
    processes = smi_processes(os.path.join(many, 'nvidia-smi.txt'))
    gpus = smi_gpus(os.path.join(many, 'gpus.csv'))
    print('| rank | pid | EGL device (of) | CUDA device | GPU UUID (the context\'s) | nvidia-smi: '
          'GPU of that UUID | nvidia-smi: process on GPU (type, memory) |')
    print('|---:|---:|---|---:|---|---:|---|')
    for r in records:
        listed = processes.get(r['pid'], [])
        print('| %d | %d | %s (%s) | %s | %s | %s | %s |' % (
            r['rank'], r['pid'], r['egl_device_index'], r['egl_devices'], r['cuda_device'],
            r['gpu_uuid'], gpus.get(r['gpu_uuid'], '?'),
            ', '.join('%d (%s, %s)' % (g, t, m) for g, t, _, m in listed) or 'not listed'))
    print()
    print('Renderer: %s; OpenGL %s; EGL vendor %s.' % (
        records[0]['gl_renderer'], records[0]['gl_version'], records[0]['egl_vendor'])
        if records else 'no ranks reported')
    print()
    check(len(records) >= 1 and all((r['egl_vendor'] or '').startswith('NVIDIA') for r in records),
          '%d rank(s) render through NVIDIA\'s EGL' % len(records))
    uuids = [r['gpu_uuid'] for r in records]
    if len(gpus) >= len(records) > 1:
        check(None not in uuids and len(set(uuids)) == len(records),
              'the %d ranks render on %d distinct GPUs' % (len(records), len(set(uuids))))
    on_own = [r for r in records if any(g == gpus.get(r['gpu_uuid']) and t in ('G', 'C+G')
                                        for g, t, _, _ in processes.get(r['pid'], []))]
    check(len(on_own) == len(records), 'nvidia-smi lists each rank\'s process (as a graphics '
          'client) on the GPU its context names: %d of %d' % (len(on_own), len(records)))
    name = 'hdr-400-300.png'
    pairs = [(os.path.join(one, name), '1 rank on GPU 0 of this machine')]
    if reference:
        pairs.append((os.path.join(reference, name), 'the one-GPU machine\'s 1-rank image'))
    for path, what in pairs:
        worst, l2 = compare(os.path.join(many, name), path) \
            if os.path.exists(path) and os.path.exists(os.path.join(many, name)) else (None, None)
        check(worst is not None and worst <= 1 and l2 <= 1e-3,
              '%d ranks\' image against %s: max %s levels, relative L2 %s' % (
                  len(records), what, worst, '%.2e' % l2 if l2 is not None else None))


MODES = {'plain': 'bloom off', 'bloom-8bit': 'bloom, 8-bit composite',
         'bloom-float': 'bloom, float composite'}


def bench(paths):
    records = [json.loads(line) for p in paths for line in open(p) if line.startswith('{')]
    records.sort(key=lambda r: (r['width'] * r['height'], r.get('gpus', r['ranks']), r['ranks'],
                                list(MODES).index(r['mode'])))

    def ms(r, key, what='mean'):
        return '%.2f' % r[key][what] if r.get(key) else '–'

    print('| GPUs (ranks) | size | mode | frame mean ms | p99 | max | IceT render | IceT '
          'composite | IceT collect | bloom (GPU) | IceT MB sent, rank 0 | frames |')
    print('|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|')
    for r in records:
        print('| %d (%d) | %dx%d | %s | %s | %s | %s | %s | %s | %s | %s | %s | %d |' % (
            r.get('gpus', r['ranks']), r['ranks'], r['width'], r['height'], MODES[r['mode']], ms(r, 'frame'),
            ms(r, 'frame', 'p99'), ms(r, 'frame', 'max'), ms(r, 'icet_render'),
            ms(r, 'icet_composite'), ms(r, 'icet_collect'), ms(r, 'bloom_gpu'),
            '%.1f' % (r['icet_bytes']['mean'] / 1e6) if r.get('icet_bytes') else '–',
            r['frame']['n']))
    strategies = {(r['strategy'], r['single_image_strategy']) for r in records if r['strategy']}
    if strategies:
        print()
        print('IceT strategy: %s.' % '; '.join('%s, single image %s' % s for s in sorted(strategies)))
    # The projection: IceT's bytes a rank sends grow as P B (1 - 1/N) for binary swap and
    # radix-k; from the largest N measured, the bytes per pixel B, then 64 ranks.
    widest = max((r['ranks'] for r in records if r.get('icet_bytes')), default=0)
    if widest > 1:
        print()
        print('| size | mode | B, bytes a pixel (from %d ranks) | 64 ranks: MB a rank | over 100 Gb/s '
              '(12.5 GB/s) | over 200 Gb/s (25 GB/s) |' % widest)
        print('|---|---|---:|---:|---:|---:|')
        for r in records:
            if r['ranks'] != widest or not r.get('icet_bytes') or r['mode'] == 'bloom-8bit':
                continue
            pixels = r['width'] * r['height']
            per_pixel = r['icet_bytes']['mean'] / (pixels * (1 - 1.0 / widest))
            sent = per_pixel * pixels * (1 - 1 / 64.0)
            print('| %dx%d | %s | %.2f | %.1f | %.2f ms | %.2f ms |' % (
                r['width'], r['height'], MODES[r['mode']], per_pixel, sent / 1e6,
                sent / 12.5e9 * 1e3, sent / 25e9 * 1e3))


if __name__ == '__main__':
    command = sys.argv[1]
    if command == 'devices':
        devices(*sys.argv[2:5])
    elif command == 'bench':
        bench(sys.argv[2:])
    elif command == 'compare':
        worst, l2 = compare(sys.argv[2], sys.argv[3])
        print('max %s levels, relative L2 %s' % (worst, l2))
    sys.exit(min(failures, 100))
