#!/usr/bin/env python3
"""Lines per file and per function of C++ sources (clang-formatted code: a function defined at
namespace scope starts at column 0 and ends at the next column-0 '}').

  python3 tools/code_size.py [--max-function N] [--max-file N] PATH...

Prints the files over --max-file lines and the functions over --max-function lines (default 80
and 400: the app layer's limits, docs/architecture.md), longest first; exit status 1 when any is
found. With no limits exceeded it prints the longest function and file it saw.
"""
import argparse
import os
import re
import sys

SIG_END = re.compile(r'\)\s*(const)?\s*(noexcept)?\s*(override)?\s*(->\s*[\w:<>,\s*&]+)?\s*\{\s*$')


def functions(lines):
    """Yields (name, first line, length) of each column-0 function definition."""
    i = 0
    while i < len(lines):
        line = lines[i]
        if line and not line[0].isspace() and not line.startswith(('//', '#', '}', 'namespace', 'struct', 'class', 'enum', 'using', 'template', 'static_assert', 'extern')) and '(' in line:
            # gather the signature up to the opening brace
            j = i
            sig = line
            while not sig.rstrip().endswith('{') and not sig.rstrip().endswith(';') and j + 1 < len(lines) and j - i < 8:
                j += 1
                sig += ' ' + lines[j].strip()
            if sig.rstrip().endswith('{') and SIG_END.search(sig) and '=' not in sig.split('(')[0]:
                k = j + 1
                while k < len(lines) and not lines[k].startswith('}'):
                    k += 1
                name = re.search(r'([\w:~]+)\s*\(', sig)
                yield (name.group(1) if name else sig[:40], i + 1, k - i + 1)
                i = k + 1
                continue
        i += 1


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--max-function', type=int, default=80)
    ap.add_argument('--max-file', type=int, default=400)
    ap.add_argument('paths', nargs='+')
    a = ap.parse_args()
    files = []
    for p in a.paths:
        if os.path.isdir(p):
            for root, _, names in os.walk(p):
                files += [os.path.join(root, n) for n in names if n.endswith(('.cpp', '.hpp'))]
        else:
            files.append(p)
    long_files, long_fns, all_fns, all_files = [], [], [], []
    for f in sorted(files):
        lines = open(f, encoding='utf-8').read().split('\n')
        n = len(lines) - (1 if lines and lines[-1] == '' else 0)
        all_files.append((n, f))
        if n > a.max_file:
            long_files.append((n, f))
        for name, start, length in functions(lines):
            all_fns.append((length, f, start, name))
            if length > a.max_function:
                long_fns.append((length, f, start, name))
    for n, f in sorted(long_files, reverse=True):
        print(f'file over {a.max_file} lines: {f}: {n}')
    for length, f, start, name in sorted(long_fns, reverse=True):
        print(f'function over {a.max_function} lines: {f}:{start} {name}: {length}')
    if not long_files and not long_fns:
        if all_fns:
            length, f, start, name = max(all_fns)
            print(f'longest function: {f}:{start} {name}: {length} lines')
        if all_files:
            n, f = max(all_files)
            print(f'longest file: {f}: {n} lines')
    return 1 if long_files or long_fns else 0


if __name__ == '__main__':
    sys.exit(main())
