# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""The file list of the ParaView GPU pack, from a traced run (scripts/paraview-gpu-pack.sh).

    python3 paraview_gpu_pack.py scan DB LD_DEBUG_FILE...
    python3 paraview_gpu_pack.py stage ROOT DB STRACE_LOG STAGE EXTRA_LIST STUBS [BUILD...]

scan reads the dynamic loader's own log of a run (LD_DEBUG=files,reloc,bindings, one file a
process) into DB (JSON, merged over calls):
- loaded: every object the loader relocated, with its path;
- used: an object is used when a symbol was bound lazily to it or from it, that is when code in
  it called, or was called through, a procedure linkage table after start-up (or dlsym found a
  symbol in it). Bindings made while an object's relocations are processed (data, vtables,
  function pointers) are load-time bindings, kept per target object with the symbol, its
  version and the object that needed it (an object relocated at once, RTLD_NOW or BIND_NOW,
  binds its calls there too: its function bindings count as uses where it is kept). Bindings
  made while an object's initializers run
  (static constructors) are kept per that object: they count only if it is kept;
- dlopened: what dlopen loaded, and by whom.

stage copies into STAGE, at the same paths, from ROOT (the sid root): every file the traced
processes opened or executed (strace -f: open, openat, execve; directories made, ELF objects
decided as below; a Python module's source for each byte-compiled file it read), the files of
EXTRA_LIST, and for ELF objects:
- the programs executed and what they and every dlopened object need, through their NEEDED
  entries, as long as the object is used (or a program, or dlopened);
- an object that is loaded only because a used object names it (NEEDED) but that nothing used
  (none of its code ran: no lazy binding to or from it in any process) is replaced by a stub of
  the same SONAME and version definitions that defines only the symbols its users bound at load
  time, each function a trap that prints the symbol and aborts, each datum zeros of the real
  size. A stub names no libraries, so what only it needed drops out. The stubs' assembly and
  version scripts are written to STUBS, with STUBS/build.sh that assembles them into STAGE
  (run in the sid root, whose assembler and linker know its objects);
- OpenGL is the machine's: glvnd's loaders, Mesa and what only they need are left out.
Writes STUBS/plan.json (what was copied, stubbed and left out, with sizes).
"""
import json
import os
import re
import shutil
import stat
import subprocess
import sys

# OpenGL's loaders and Mesa's drivers: the GPU machine's own (glvnd and the NVIDIA driver).
GL = re.compile(r'^(libEGL|libGL|libGLX|libGLdispatch|libOpenGL|libGLES|libgallium|libgbm|'
                r'libEGL_mesa|libGLX_mesa|libglapi|libvulkan|libLLVM|libxcb-dri|'
                r'libxshmfence|libwayland-|libVkLayer|libvdpau|libva)|_dri\.so|_drv_video')
GL_DATA = ('/usr/share/glvnd/', '/usr/share/drirc.d/', '/etc/drirc', '/usr/share/libdrm/',
           '/usr/share/vulkan/', '/etc/ld.so.cache')
SKIP_PREFIX = ('/proc/', '/sys/', '/dev/', '/tmp/', '/run/', '/root/', '/var/tmp/', '/work/',
               '/etc/resolv.conf', '/etc/hostname', '/out/', '/reference/')
# glibc whole: the machine's driver libraries link its compatibility libraries (libdl,
# libpthread, librt), which nothing in the traced run loaded.
GLIBC = ('libc.so.6', 'libm.so.6', 'libdl.so.2', 'libpthread.so.0', 'librt.so.1',
         'libutil.so.1', 'libresolv.so.2', 'libanl.so.1', 'libmvec.so.1', 'libnss_files.so.2',
         'libnss_dns.so.2', 'ld-linux-x86-64.so.2', 'libgcc_s.so.1')

BIND = re.compile(r"binding file (.*?) \[\d+\] to (.*?) \[\d+\]: (?:normal|protected) symbol "
                  r"`(.*?)'(?: \[(.*?)\])?")
# The loader's lines that end a relocation or an initializer phase.
MARKERS = ('relocation processing: ', 'calling init: ', 'calling fini: ', 'file=', 'opening file=',
           'closing file=', 'transferring control: ', 'initialize program: ')
DLOPEN = re.compile(r"file=(.*?) \[\d+\];\s+dynamically loaded by (.*?) \[\d+\]")


def scan(db_path, logs):
    db = json.load(open(db_path)) if os.path.exists(db_path) else {}
    loaded = set(db.get('loaded', []))
    used = set(db.get('used', []))
    dlopened = {tuple(x) for x in db.get('dlopened', [])}
    loadtime = {k: {tuple(x) for x in v} for k, v in db.get('loadtime', {}).items()}
    init = {k: set(v) for k, v in db.get('init', {}).items()}
    eager = set(db.get('eager', []))
    for path in logs:
        current = owner = None
        with open(path, errors='replace') as f:
            for line in f:
                tab = line.find('\t')
                text = line[tab + 1:].rstrip('\n') if tab >= 0 else line.strip()
                if not text.strip():
                    continue  # the loader's blank separator lines end nothing
                if text.startswith('binding file '):
                    m = BIND.match(text)
                    if not m:
                        continue
                    a, b, symbol, version = m.groups()
                    if current is not None and a == current:
                        loadtime.setdefault(b, set()).add((symbol, version or '', a))
                    elif owner is not None:
                        # While an object's initializers run: what they call is used only if
                        # that object is kept (its initializers then run there too).
                        init.setdefault(owner, set()).update((a, b))
                    else:
                        used.add(a)
                        used.add(b)
                    continue
                if not text.startswith(MARKERS):
                    continue  # a long binding line's continuation, or the loader's detail
                current = owner = None
                if text.startswith('relocation processing: '):
                    current = text[len('relocation processing: '):]
                    if current.endswith(' (lazy)'):
                        current = current[:-len(' (lazy)')]
                    else:
                        eager.add(current)  # RTLD_NOW or BIND_NOW: calls bound here too
                    loaded.add(current)
                    continue
                if text.startswith('calling init: '):
                    owner = text[len('calling init: '):]
                    continue
                m = DLOPEN.search(text)
                if m:
                    dlopened.add(m.groups())
    db = {'loaded': sorted(loaded), 'used': sorted(used), 'dlopened': sorted(dlopened),
          'loadtime': {k: sorted(v) for k, v in loadtime.items()},
          'init': {k: sorted(v) for k, v in init.items()}, 'eager': sorted(eager)}
    with open(db_path + '.tmp', 'w') as f:
        json.dump(db, f)
    os.replace(db_path + '.tmp', db_path)
    print('scan: %d objects loaded, %d used, %d dlopen calls' % (
        len(loaded), len(used), len(dlopened)))


class Root:
    """Paths inside ROOT, resolved as the processes inside it saw them."""

    def __init__(self, root):
        self.root = os.path.abspath(root)

    def host(self, path):
        return self.root + path

    def resolve(self, path, links=None, depth=0):
        """The canonical path inside the root (symbolic links followed, component by
        component); links collects (link, target) pairs met on the way."""
        if depth > 40:
            return None
        parts = [p for p in os.path.normpath('/' + path).split('/') if p]
        resolved = ''
        for i, part in enumerate(parts):
            if part == '..':
                resolved = os.path.dirname(resolved)
                continue
            candidate = resolved + '/' + part
            full = self.host(candidate)
            if os.path.islink(full):
                target = os.readlink(full)
                if links is not None:
                    links.append((candidate, target))
                base = target if target.startswith('/') else os.path.dirname(candidate) + '/' + target
                rest = '/'.join(parts[i + 1:])
                return self.resolve(base + ('/' + rest if rest else ''), links, depth + 1)
            resolved = candidate
        return resolved or '/'

    def exists(self, path):
        return os.path.lexists(self.host(path))


def elf_info(path):
    """(is ELF, SONAME, NEEDED list, e_type, BIND_NOW) of a file, by readelf."""
    with open(path, 'rb') as f:
        if f.read(4) != b'\x7fELF':
            return False, None, [], None, False
    out = subprocess.run(['readelf', '-dhW', path], capture_output=True, text=True).stdout
    soname = re.search(r'\(SONAME\)\s+Library soname: \[(.*?)\]', out)
    needed = re.findall(r'\(NEEDED\)\s+Shared library: \[(.*?)\]', out)
    kind = re.search(r'Type:\s+(\w+)', out)
    now = bool(re.search(r'\(FLAGS\)\s+.*BIND_NOW|\(FLAGS_1\)\s+.*\bNOW\b', out))
    return True, soname.group(1) if soname else None, needed, kind.group(1) if kind else None, now


def dynamic_symbols(path):
    """{(name, version): (type, size, default)} of an object's defined dynamic symbols."""
    out = subprocess.run(['readelf', '--dyn-syms', '-W', path], capture_output=True,
                         text=True).stdout
    symbols = {}
    for line in out.splitlines():
        fields = line.split()
        if len(fields) < 8 or not fields[0].rstrip(':').isdigit() or fields[6] == 'UND':
            continue
        name = fields[7]
        version, default = '', True
        if '@@' in name:
            name, version = name.split('@@', 1)
        elif '@' in name:
            name, version = name.split('@', 1)
            default = False
        version = re.sub(r' \(\d+\)$', '', version)
        size = int(fields[2], 0) if fields[2].startswith('0x') else int(fields[2])
        symbols[(name, version)] = (fields[3], size, default)
    return symbols


def version_definitions(path):
    """The version nodes an object defines (readelf -V), the base (its SONAME) left out."""
    out = subprocess.run(['readelf', '-VW', path], capture_output=True, text=True).stdout
    section = out.split("Version definition section '.gnu.version_d'")
    if len(section) < 2:
        return []
    section = section[1].split("Version needs section")[0]
    nodes = []
    for m in re.finditer(r'Flags: (\S+)\s+Index: \d+\s+Cnt: \d+\s+Name: (\S+)', section):
        if m.group(1) != 'BASE':
            nodes.append(m.group(2))
    return nodes


def stub_source(real, soname, wanted):
    """Assembly and version script of a stub for real: the (symbol, version) pairs wanted."""
    symbols = dynamic_symbols(real)
    nodes = version_definitions(real)
    asm = ['\t.text', '__vtkbloom_stub_die:', '\tmov $2, %edi', '\tmov $1, %eax', '\tsyscall',
           '\tud2']
    data, text_msgs, script = [], [], {n: [] for n in nodes}
    unversioned = []
    for k, (name, version) in enumerate(sorted(wanted)):
        entry = symbols.get((name, version)) or next(
            (v for (n, ver), v in symbols.items() if n == name and (not version or ver == version)),
            None)
        kind, size, default = entry if entry else ('FUNC', 0, True)
        label = '__vtkbloom_stub_%d' % k
        if version and version in script and default:
            script[version].append(name)
            exported = name
        elif version and version in script:
            exported = None  # a non-default version: .symver below
        else:
            unversioned.append(name)
            exported = name
        if kind in ('FUNC', 'IFUNC', 'NOTYPE'):
            message = 'vtk-bloom pack: %s called, but %s is a stub\n' % (name, soname)
            text_msgs.append('%s_msg: .ascii "%s"' % (label, message.replace('\n', '\\n')))
            asm += ['\t.globl %s' % label, '\t.type %s, @function' % label, '%s:' % label,
                    '\tlea %s_msg(%%rip), %%rsi' % label, '\tmov $%d, %%edx' % len(message),
                    '\tjmp __vtkbloom_stub_die']
        elif kind == 'TLS':
            data += ['\t.section .tbss,"awT",@nobits', '\t.balign 16', '\t.globl %s' % label,
                     '\t.type %s, @object' % label, '\t.size %s, %d' % (label, max(size, 1)),
                     '%s:' % label, '\t.zero %d' % max(size, 1)]
        else:
            data += ['\t.data', '\t.balign 16', '\t.globl %s' % label,
                     '\t.type %s, @object' % label, '\t.size %s, %d' % (label, max(size, 1)),
                     '%s:' % label, '\t.zero %d' % max(size, 1)]
        if exported is None:
            asm.append('\t.symver %s, %s@%s' % (label, name, version))
        else:
            asm += ['\t.globl "%s"' % name, '\t.set "%s", %s' % (name, label)]
            if kind in ('FUNC', 'IFUNC', 'NOTYPE'):
                asm.append('\t.type "%s", @function' % name)
            else:
                asm += ['\t.type "%s", @%s' % (name, 'tls_object' if kind == 'TLS' else 'object'),
                        '\t.size "%s", %d' % (name, max(size, 1))]
    source = '\n'.join(asm + ['\t.section .rodata'] + text_msgs + data +
                       ['\t.section .note.GNU-stack,"",@progbits', ''])
    version_script = None
    if nodes:
        lines, previous = [], None
        for i, node in enumerate(nodes):
            names = script[node] + (unversioned if i == 0 else [])
            body = ''.join('"%s";' % n for n in names)
            lines.append('%s { %s %s }%s;' % (node, 'global: ' + body if names else '',
                                               'local: *;' if i == 0 else '',
                                               ' ' + previous if previous else ''))
            previous = node
        version_script = '\n'.join(lines) + '\n'
    return source, version_script


def stage(root_dir, db_path, strace_log, stage_dir, extra_list, stubs_dir, *builds):
    root = Root(root_dir)
    db = json.load(open(db_path))
    os.makedirs(stage_dir, exist_ok=True)
    os.makedirs(stubs_dir, exist_ok=True)
    build = ['set -e', 'cd "$(dirname "$0")"']

    def canon(path):
        return root.resolve(path) if path else None

    used = {canon(p) for p in db['used']}
    loaded = {canon(p) for p in db['loaded']}
    loadtime = {}
    for target, entries in db['loadtime'].items():
        loadtime.setdefault(canon(target), []).extend(entries)

    # What the traced processes opened and executed, as they named it.
    opened, executed, directories = set(), set(), set()
    call = re.compile(r'^(\d+)\s+(openat|open|execve|newfstatat|statx|stat|access)'
                      r'\((?:AT_FDCWD, |\d+, )?"(.*?)"(.*)$')
    result = re.compile(r'= (-?\d+)')
    resumed = re.compile(r'^(\d+)\s+<\.\.\. (\w+) resumed>(.*)$')
    unfinished = {}

    def record(name, path, rest):
        m = result.search(rest)
        if not m or int(m.group(1)) < 0 or not path.startswith('/'):
            return
        if name == 'execve':
            executed.add(path)
        elif name in ('openat', 'open'):
            (directories if 'O_DIRECTORY' in rest else opened).add(path)
        else:
            opened.add(('stat', path))

    for line in open(strace_log, errors='replace'):
        m = call.match(line)
        if m:
            pid, name, path, rest = m.groups()
            if rest.endswith('<unfinished ...>'):
                unfinished[pid] = (name, path, rest)
            else:
                record(name, path, rest)
            continue
        m = resumed.match(line)
        if m and m.group(1) in unfinished:
            name, path, rest = unfinished.pop(m.group(1))
            record(name, path, rest + m.group(3))

    # ELF facts of every object the processes loaded or executed.
    facts, by_soname = {}, {}

    def fact(path):
        if path not in facts:
            host = root.host(path)
            facts[path] = elf_info(host) if os.path.isfile(host) else (False, None, [], None, False)
            if facts[path][1]:
                by_soname.setdefault(facts[path][1], path)
        return facts[path]

    for p in loaded:
        if p and root.exists(p):
            fact(p)

    def is_gl(path):
        return bool(GL.search(os.path.basename(path)))

    def needed_path(soname, user):
        if soname in by_soname:
            return by_soname[soname]
        for d in ('/usr/lib/x86_64-linux-gnu', '/usr/lib', '/usr/local/lib'):
            if root.exists(d + '/' + soname):
                p = canon(d + '/' + soname)
                fact(p)
                return p
        return None

    roots = set()
    for p in executed:
        c = canon(p)
        if c and root.exists(c) and fact(c)[0]:
            roots.add(c)
    for name, by in db['dlopened']:
        by_c = canon(by)
        if by_c and is_gl(by_c):
            continue
        target = canon(name) if name.startswith('/') else needed_path(name, by_c)
        if target and not is_gl(target) and root.exists(target):
            roots.add(target)
    for lib in GLIBC:
        p = needed_path(lib, None)
        if p:
            roots.add(p)
    # The project's own objects (the plugin, the vtkbloom package, vtk-bloom), which the pack
    # script copies: what they name from the root is carried as a program's needs are.
    for build_dir in builds:
        for directory, _, files in os.walk(build_dir):
            if '/CMakeFiles' in directory:
                continue
            for name in files:
                path = os.path.join(directory, name)
                if os.path.islink(path) or not ('.so' in name or name == 'vtk-bloom'):
                    continue
                info = elf_info(path)
                for soname in info[2] if info[0] else []:
                    if os.path.exists(os.path.join(directory, soname)):
                        continue  # the project's own, beside it
                    child = needed_path(soname, None)
                    if child and not is_gl(child):
                        roots.add(child)

    # Initializers: what an object's initializers called is used if that object is kept.
    init = {}
    for owner, touched in db.get('init', {}).items():
        init.setdefault(canon(owner), set()).update(canon(t) for t in touched)
    # An object linked with BIND_NOW binds every function it calls while it is relocated, so
    # its load-time bindings may be calls: they count as uses where it is kept.
    # So does an object relocated at once (dlopen with RTLD_NOW, as Python imports its
    # extension modules, and what they bring in): its bindings of functions may be calls.
    eager_objects = {canon(p) for p in db.get('eager', [])}
    functions = {}

    def is_function(target, symbol, version):
        if target not in functions:
            host = root.host(target)
            functions[target] = {k for k, v in dynamic_symbols(host).items()
                                 if v[0] in ('FUNC', 'IFUNC')} if os.path.isfile(host) else set()
        return (symbol, version) in functions[target] or (symbol, '') in functions[target]

    eager = {}
    for target, entries in loadtime.items():
        for symbol, version, by in entries:
            by_c = canon(by) if '/' in by else None
            if by_c and (by_c in eager_objects or (root.exists(by_c) and fact(by_c)[4])) and \
                    target not in eager.get(by_c, ()) and is_function(target, symbol, version):
                eager.setdefault(by_c, set()).add(target)
    # Plugins that a library loads to probe a device or a transport (hwloc's, Open MPI's, UCX's,
    # PMIx's; not Python's extension modules): what they name is carried as it is, since a probe
    # that found nothing in the trace (hwloc's OpenCL plugin on llvmpipe) may call it elsewhere.
    probes = {r for r in roots if fact(r)[3] == 'DYN' and '/python3' not in r and
              not r.endswith(tuple(GLIBC)) and '/bin/' not in r}
    keep, gl_out = set(), set()
    while True:
        stubs = set()
        live = used | roots | set().union(set(), *(init.get(k, set()) | eager.get(k, set())
                                                    for k in keep))
        pending, seen = sorted(roots), set()
        kept = set()
        while pending:
            p = pending.pop()
            if p in seen:
                continue
            seen.add(p)
            kept.add(p)
            for soname in fact(p)[2]:
                child = needed_path(soname, p)
                if child is None:
                    print('stage: %s needs %s, not found' % (p, soname))
                    continue
                if is_gl(child):
                    gl_out.add(child)
                elif child in live or child not in loaded or p in probes:
                    # Used, or not loaded in the trace at all (needed by an object that was,
                    # never reached there): the real one, to be safe.
                    pending.append(child)
                else:
                    stubs.add(child)
        stubs -= kept
        if kept == keep:
            break
        keep = kept
    copied = {}

    def add(path, content_from=None):
        """Copy path (and every link on the way) from the root into the stage."""
        links = []
        real = root.resolve(path, links)
        for link, target in links:
            dest = stage_dir + link
            if not os.path.lexists(dest):
                os.makedirs(os.path.dirname(dest), exist_ok=True)
                os.symlink(target, dest)
        if real is None or not root.exists(real):
            return None
        host = root.host(real)
        dest = stage_dir + real
        if os.path.isdir(host) and not os.path.islink(host):
            os.makedirs(dest, exist_ok=True)
            return real
        if not os.path.exists(dest):
            os.makedirs(os.path.dirname(dest), exist_ok=True)
            shutil.copy2(host, dest)
            copied[real] = os.path.getsize(host)
        return real

    def skipped(path):
        return path.startswith(SKIP_PREFIX) or path.startswith(GL_DATA)

    # The objects, and the names the programs were run by (python3 -> python3.14).
    for p in sorted(keep):
        add(p)
    for p in sorted(executed):
        if canon(p) in keep:
            add(p)
    plan_stubs = {}
    for p in sorted(stubs):
        real = add(p)
        if real is None:
            continue
        soname = fact(p)[1] or os.path.basename(p)
        # The main program is named as it was run (no '/'): it is kept.
        wanted = {(s, v) for s, v, by in loadtime.get(p, []) if '/' not in by or canon(by) in keep}
        source, script = stub_source(root.host(real), soname, wanted)
        key = re.sub(r'[^A-Za-z0-9_.-]', '_', real.lstrip('/'))
        with open(os.path.join(stubs_dir, key + '.S'), 'w') as f:
            f.write(source)
        if script:
            with open(os.path.join(stubs_dir, key + '.map'), 'w') as f:
                f.write(script)
        plan_stubs[real] = {'soname': soname, 'key': key, 'symbols': len(wanted),
                            'size': os.path.getsize(root.host(real))}
        build.append("gcc -shared -nostdlib -Wl,-soname,'%s' -Wl,-z,noexecstack %s -o '%s' %s.S"
                     % (soname, "-Wl,--version-script=%s.map" % key if script else '',
                        stage_dir + real, key))
        copied.pop(real, None)
    # Every other file the processes read: not ELF objects (decided above), not the machine's.
    for entry in sorted(opened, key=str):
        path = entry[1] if isinstance(entry, tuple) else entry
        if skipped(path) or not root.exists(path):
            continue
        real = root.resolve(path)
        if real is None or skipped(real) or not os.path.isfile(root.host(real)):
            continue
        if isinstance(entry, tuple) and os.path.getsize(root.host(real)) > (1 << 20):
            continue  # only stat-ed: small files only
        if real.endswith('.pyc'):
            # A module's compiled form: carry its source instead, Python compiles it there.
            m = re.match(r'^(.*)/__pycache__/([^/.]+)\.cpython-\d+(?:\.opt-\d)?\.pyc$', real)
            if m and root.exists('%s/%s.py' % m.groups()):
                add('%s/%s.py' % m.groups())
            continue
        is_elf = fact(real)[0] if real.endswith(('.so',)) or '.so.' in real or \
            real.startswith(('/usr/bin/', '/usr/sbin/', '/usr/lib/')) else False
        if is_elf and real not in keep:
            continue
        add(path)
    for path in sorted(directories):
        if not skipped(path) and root.exists(path) and os.path.isdir(root.host(root.resolve(path) or '/')):
            add(path)
    for line in open(extra_list):
        path = line.strip()
        if path and not path.startswith('#') and root.exists(path):
            add(path)
    plan = {'copied': copied, 'stubs': plan_stubs, 'gl_left_out': sorted(gl_out),
            'kept_objects': sorted(keep)}
    with open(os.path.join(stubs_dir, 'plan.json'), 'w') as f:
        json.dump(plan, f, indent=1)
    with open(os.path.join(stubs_dir, 'build.sh'), 'w') as f:
        f.write('\n'.join(build) + '\n')
    total = sum(copied.values())
    stubbed = sum(s['size'] for s in plan_stubs.values())
    print('stage: %d files (%.1f MB), %d objects kept, %d stubbed (%.1f MB left out), %d GL '
          'objects left to the machine' % (len(copied), total / 1e6, len(keep), len(plan_stubs),
                                          stubbed / 1e6, len(gl_out)))


if __name__ == '__main__':
    if sys.argv[1] == 'scan':
        scan(sys.argv[2], sys.argv[3:])
    elif sys.argv[1] == 'stage':
        stage(*sys.argv[2:])
    else:
        sys.exit('usage: paraview_gpu_pack.py scan DB LOG... | stage ROOT DB STRACE STAGE EXTRA STUBS [BUILD]')
