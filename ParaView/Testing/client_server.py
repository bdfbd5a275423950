# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""Run a pvpython client script against a pvserver of N ranks, on this machine, loopback only.

    python3 client_server.py RANKS SCRIPT [ARGS...]      (run by scripts/pvserver.sh)

Run in a network namespace of its own (scripts/pvserver.sh starts it with `unshare -n`), where
the only interface is the loopback: the server cannot be reached from anywhere else. This
driver brings the loopback up, starts `pvserver` (through mpiexec for more than one rank) on
port 11111 with offscreen rendering, waits up to 60 s for it to accept connections, runs
`pvpython SCRIPT --server 11111 ARGS...` with a 240 s limit, then stops the server (its whole
process group, killed if it does not exit within 10 s). The exit status is the client's, or
124 when a wait timed out. VTKBLOOM_PVSERVER_ARGS adds arguments to pvserver's (a tile
display: --tdx=2 --tdy=1); VTKBLOOM_PVSERVER_LOG keeps the server's output in that file.
"""
import fcntl
import os
import signal
import socket
import struct
import subprocess
import sys
import tempfile
import time

PORT = 11111


def loopback_up():
    """Bring `lo` up (a new network namespace starts with it down), as `ip link set lo up`."""
    SIOCGIFFLAGS, SIOCSIFFLAGS, IFF_UP = 0x8913, 0x8914, 0x1
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        request = struct.pack('16sH14x', b'lo', 0)
        flags = struct.unpack('16sH14x', fcntl.ioctl(s, SIOCGIFFLAGS, request))[1]
        fcntl.ioctl(s, SIOCSIFFLAGS, struct.pack('16sH14x', b'lo', flags | IFF_UP))


def stop(process):
    try:
        os.killpg(process.pid, signal.SIGTERM)
        process.wait(timeout=10)
    except (ProcessLookupError, subprocess.TimeoutExpired):
        try:
            os.killpg(process.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        process.wait()


def main():
    ranks, script, args = int(sys.argv[1]), sys.argv[2], sys.argv[3:]
    loopback_up()
    server = ['pvserver', '--server-port=%d' % PORT, '--hostname=localhost',
              '--force-offscreen-rendering']
    server += os.environ.get('VTKBLOOM_PVSERVER_ARGS', '').split()
    if ranks > 1:
        server = ['mpiexec', '-n', str(ranks)] + server
    log_path = os.environ.get('VTKBLOOM_PVSERVER_LOG') or os.path.join(
        tempfile.mkdtemp(prefix='pvserver-'), 'server.log')
    with open(log_path, 'w') as log:
        process = subprocess.Popen(server, stdout=log, stderr=subprocess.STDOUT,
                                   start_new_session=True)
    try:
        deadline = time.monotonic() + 60
        ready = False
        while time.monotonic() < deadline and process.poll() is None:
            with open(log_path, errors='replace') as log:
                if 'Accepting connection' in log.read():
                    ready = True
                    break
            time.sleep(0.1)
        if not ready:
            print('client_server: pvserver (%d ranks) did not accept connections within 60 s'
                  % ranks, file=sys.stderr)
            return 124
        client = ['pvpython', '--force-offscreen-rendering', script, '--server', str(PORT)] + args
        try:
            return subprocess.run(client, timeout=240).returncode
        except subprocess.TimeoutExpired:
            print('client_server: the client did not finish within 240 s', file=sys.stderr)
            return 124
    finally:
        stop(process)


if __name__ == '__main__':
    sys.exit(main())
