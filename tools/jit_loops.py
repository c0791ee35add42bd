#!/usr/bin/env python3
"""What llvmpipe's JIT makes of the light pass: the x86 instructions of each light loop.

Runs `halfvec bench --lights N` long enough to sample it with perf, finds the hottest JIT code
region (the light pass: llvmpipe compiles shaders to anonymous executable memory), dumps it from
the running process with gdb, disassembles it with objdump and prints, for every loop of at least
--min-loop instructions (the per-type light loops of shaders/passes/light_shade.comp, each
evaluating HV_LIGHT_PIXELS pixels per iteration), its instruction mix and its share of the
samples. docs/lights.md ("Light pass throughput") quotes its output.

Needs perf, gdb and objdump (Debian: linux-perf gdb binutils) and permission to attach to a
child process (ptrace; root, or kernel.yama.ptrace_scope = 0). Not part of the test suite.

  python3 tools/jit_loops.py [--halfvec build/halfvec] [--lights 1024] [--types mixed]
"""
import argparse
import collections
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time


def run(cmd, **kw):
    return subprocess.run(cmd, check=True, capture_output=True, text=True, **kw)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--halfvec", default="build/halfvec")
    ap.add_argument("--lights", type=int, default=1024)
    ap.add_argument("--types", default="mixed")
    ap.add_argument("--seconds", type=float, default=5.0, help="perf sampling time")
    ap.add_argument("--min-loop", type=int, default=200, help="smallest loop reported")
    a = ap.parse_args()
    for tool in ("perf", "gdb", "objdump"):
        if not shutil.which(tool):
            sys.exit(f"jit_loops: '{tool}' not found (Debian: apt install linux-perf gdb binutils)")
    if not os.access(a.halfvec, os.X_OK):
        sys.exit(f"jit_loops: no executable '{a.halfvec}' (build first: bash scripts/build.sh)")

    tmp = tempfile.mkdtemp(prefix="hv_jit_")
    bench = subprocess.Popen(
        [a.halfvec, "bench", "--lights", str(a.lights), "--types", a.types, "--frames", "100000"],
        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        time.sleep(4.0)  # context, scene, program compiles
        if bench.poll() is not None:
            sys.exit("jit_loops: the bench exited early")
        data = os.path.join(tmp, "perf.data")
        run(["perf", "record", "-F", "4999", "-p", str(bench.pid), "-o", data, "--", "sleep",
             str(a.seconds)])
        ips = collections.Counter()
        for line in run(["perf", "script", "-i", data, "-F", "ip"]).stdout.split():
            ips[int(line, 16)] += 1
        total = sum(ips.values())
        # Clusters of sampled addresses (gaps under 4 KiB); the hottest is the light pass.
        clusters = []
        for ip in sorted(ips):
            if clusters and ip - clusters[-1][1] < 4096:
                clusters[-1][1] = ip
                clusters[-1][2] += ips[ip]
            else:
                clusters.append([ip, ip, ips[ip]])
        lo, hi, hot = max(clusters, key=lambda c: c[2])
        lo &= ~0xFFF
        hi = (hi + 0x1000) & ~0xFFF
        dump = os.path.join(tmp, "code.bin")
        run(["gdb", "-p", str(bench.pid), "-batch", "-ex",
             f"dump binary memory {dump} {lo:#x} {hi:#x}"])
    finally:
        bench.kill()
        bench.wait()
    asm = run(["objdump", "-D", "-b", "binary", "-m", "i386:x86-64", f"--adjust-vma={lo:#x}",
               dump]).stdout
    rows = []
    for line in asm.splitlines():
        m = re.match(r"\s*([0-9a-f]+):\s+(?:[0-9a-f]{2} )+\s*(\S.*)?$", line)
        if m and m.group(2):
            rows.append((int(m.group(1), 16), m.group(2).strip()))
    index = {addr: i for i, (addr, _) in enumerate(rows)}
    print(f"hottest JIT region {lo:#x}-{hi:#x}: {100.0 * hot / total:.1f}% of {total} samples")
    print(f"{'loop':>14} {'instr':>6} {'samples%':>8} {'div':>4} {'sqrt':>4} {'mul':>4} "
          f"{'add/sub':>7} {'fma':>4} {'min/max':>7} {'stack':>5} {'call':>4}")
    for i, (addr, ins) in enumerate(rows):
        m = re.match(r"j\w+\s+0x([0-9a-f]+)", ins)
        if not m:
            continue
        target = int(m.group(1), 16)
        if target >= addr or target not in index or i - index[target] + 1 < a.min_loop:
            continue
        body = rows[index[target]:i + 1]
        ops = [b[1].split()[0] for b in body]
        samples = sum(ips.get(b[0], 0) for b in body)
        print(f"{target:#14x} {len(body):6d} {100.0 * samples / total:8.1f} "
              f"{ops.count('vdivps'):4d} {ops.count('vsqrtps'):4d} {ops.count('vmulps'):4d} "
              f"{ops.count('vaddps') + ops.count('vsubps'):7d} "
              f"{sum(o.startswith('vfmadd') or o.startswith('vfmsub') for o in ops):4d} "
              f"{ops.count('vminps') + ops.count('vmaxps'):7d} "
              f"{sum(('rsp' in b[1]) or ('rbp' in b[1]) for b in body):5d} "
              f"{ops.count('call'):4d}")
    shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
