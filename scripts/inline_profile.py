#!/usr/bin/env python3
"""Instructions of one function by the source line it was inlined from, calls included.

callgrind_annotate sums instructions by file:line, so the vector arithmetic that GCC
inlines into the path loop from a dozen helpers lands on vec.h's few lines, whoever
called them. This walks each instruction's inline chain (addr2line -i) instead, and
charges it and the calls made from it (Embree's included) to the line of FUNCTION that
it came from, DEPTH levels of inlining down (0: FUNCTION's own lines).

  valgrind --tool=callgrind --dump-instr=yes --callgrind-out-file=cg.out \\
      --toggle-collect='*render_samples*' BUILD-WITH-G/penumbra render ...
  scripts/inline_profile.py cg.out BUILD-WITH-G/penumbra 'PathIntegrator::trace<false, false>' 1

A build with -g (CMAKE_CXX_FLAGS_RELEASE="-O3 -DNDEBUG -g") keeps the inline records.
Columns: the instructions executed at that site, those of the calls made from it, and
the site (FUNCTION's line | the inlined frames below it).
"""
import collections
import re
import subprocess
import sys


def parse(path, pattern):
    """(self, calls): instructions per address of the functions whose names match."""
    names, self_cost, call_cost = {}, collections.Counter(), collections.Counter()
    in_target, pending_call, addr = False, False, 0

    def name_of(text):
        m = re.match(r'\((\d+)\)(?: (.*))?', text)
        if m.group(2):
            names[m.group(1)] = m.group(2)
        return names[m.group(1)]

    def position(token, previous):
        if token == '*':
            return previous
        if token[0] in '+-':
            return previous + int(token, 0)
        return int(token, 0)

    with open(path) as f:
        for line in f:
            line = line.rstrip('\n')
            if not line:
                continue
            if line.startswith('fn='):
                in_target = re.search(pattern, name_of(line[3:])) is not None
            elif line.startswith('cfn='):
                name_of(line[4:])
            elif line.startswith('calls='):
                pending_call = True
            elif line[0] in '0123456789+-*':
                tokens = line.split()  # positions "instr line", then the cost
                addr = position(tokens[0], addr)
                if in_target and len(tokens) > 2:
                    (call_cost if pending_call else self_cost)[addr] += int(tokens[-1])
                pending_call = False
    return self_cost, call_cost


def inline_chains(binary, addrs):
    """Outermost-first [(function, file:line)] per address."""
    out = subprocess.run(['addr2line', '-i', '-f', '-C', '-a', '-e', binary] +
                         [hex(a) for a in addrs], capture_output=True, text=True,
                         check=True).stdout.splitlines()
    chains, current, i = {}, None, 0
    while i < len(out):
        if out[i].startswith('0x'):
            current = int(out[i], 16)
            chains[current] = []
            i += 1
        else:
            chains[current].append((out[i], out[i + 1]))
            i += 2
    return {a: c[::-1] for a, c in chains.items()}


def short(function, location):
    function = re.sub(r'\(.*', '', function).replace('penumbra::', '')
    return function + '@' + location.split('/')[-1].split(' ')[0]


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    path, binary, pattern = sys.argv[1:4]
    depth = int(sys.argv[4]) if len(sys.argv) > 4 else 1
    self_cost, call_cost = parse(path, pattern)
    addrs = sorted(set(self_cost) | set(call_cost))
    chains = inline_chains(binary, addrs)
    own, calls = collections.Counter(), collections.Counter()
    for a in addrs:
        chain = chains.get(a) or [('?', '?')]
        site = chain[0][1].split('/')[-1].split(' ')[0]
        below = ' > '.join(short(f, l) for f, l in chain[1:depth + 1])
        key = site + (' | ' + below if below else '')
        own[key] += self_cost[a]
        calls[key] += call_cost[a]
    total = sum(own.values()) + sum(calls.values())
    print('%d instructions, %d of them in %s itself' % (total, sum(own.values()), pattern))
    for key in sorted(own, key=lambda k: -(own[k] + calls[k]))[:60]:
        print('%12d %12d  %s' % (own[key], calls[key], key))


if __name__ == '__main__':
    main()
