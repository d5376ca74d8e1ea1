#!/usr/bin/env python3
"""Where the pipeline's time goes, from `perf script` output of a perf record with call graphs.

    perf record -F 999 --call-graph dwarf,16384 -o perf.data -- \
        build/bench/diffuv_performance_bench --perf-loop paper --mesh man --level 0 --repeat 150
    perf script -i perf.data | python3 scripts/perf_stages.py [--root parameterize_patches] [--top 25]
    perf script -i perf.data | python3 scripts/perf_stages.py --root Multi_source_dijkstra::run \
        --within parameterize_patches --depth 4       # inside one function, pipeline samples only

Only samples whose call chain passes through the root function count (the
pipeline, not the mesh set-up). Prints (1) the share of each function called
directly by the root (a "stage", inlined calls included), (2) the share of
each leaf function (self time), (3) the top (stage, leaf) pairs. Template
arguments are removed from names.
"""
import argparse
import collections
import re
import sys


def clean(symbol):
    symbol = re.sub(r"\+0x[0-9a-f]+$", "", symbol.strip())
    out, depth = [], 0
    for ch in symbol:  # drop template arguments and parameter lists
        if ch in "<(":
            depth += 1
        elif ch in ">)":
            depth = max(0, depth - 1)
        elif depth == 0:
            out.append(ch)
    name = "".join(out).replace("(anonymous namespace)::", "")
    return name.strip() or symbol


def samples(lines):
    frames = []
    for line in lines:
        if not line.strip():
            if frames:
                yield frames
            frames = []
            continue
        if line[0] not in " \t":
            continue  # the sample's header line
        parts = line.strip().split(" ", 1)
        if len(parts) < 2:
            continue
        sym = re.sub(r"\s+\((inlined|[^)]*/[^)]*|\[kernel\.kallsyms\])\)\s*$", "", parts[1])
        frames.append(clean(sym))
    if frames:
        yield frames


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--root", default="parameterize_patches")
    ap.add_argument("--top", type=int, default=25)
    ap.add_argument("--depth", type=int, default=3, help="levels below the root shown in the call-tree listing")
    ap.add_argument("--within", default=None,
                    help="count only samples whose chain also passes through this function (e.g. parameterize_patches)")
    a = ap.parse_args()
    tree = collections.Counter()
    total = in_root = 0
    stage = collections.Counter()
    leaf = collections.Counter()
    pair = collections.Counter()
    for frames in samples(sys.stdin):
        total += 1
        idx = [i for i, f in enumerate(frames) if f.endswith(a.root)]
        if not idx or (a.within and not any(f.endswith(a.within) for f in frames)):
            continue
        in_root += 1
        r = idx[-1]  # outermost occurrence
        s = frames[r - 1] if r > 0 else "(self)"
        stage[s] += 1
        leaf[frames[0]] += 1
        pair[(s, frames[0])] += 1
        for d in range(1, a.depth + 1):  # inclusive counts of call paths below the root
            if r - d < 0:
                break
            tree[tuple(frames[r - d:r][::-1])] += 1
    print(f"{in_root} of {total} samples ({100.0 * in_root / max(total, 1):.1f} %) in {a.root}\n")
    print("stage (called by the root, inclusive)            share")
    for s, n in stage.most_common(a.top):
        print(f"  {s[:60]:60s} {100.0 * n / in_root:6.2f} %")
    print("\ncall paths below the root (inclusive, >= 1 %)")
    def show(prefix):
        children = [(p, n) for p, n in tree.items() if len(p) == len(prefix) + 1 and p[:len(prefix)] == prefix]
        for p, n in sorted(children, key=lambda x: -x[1]):
            if 100.0 * n / in_root < 1.0:
                continue
            print(f"  {'  ' * len(prefix)}{p[-1][:70]:70s} {100.0 * n / in_root:6.2f} %")
            show(p)
    show(())
    print("\nleaf (self time)                                    share")
    for s, n in leaf.most_common(a.top):
        print(f"  {s[:60]:60s} {100.0 * n / in_root:6.2f} %")
    print("\nstage -> leaf                                         share")
    for (s, l), n in pair.most_common(a.top):
        print(f"  {s[:40]:40s} -> {l[:45]:45s} {100.0 * n / in_root:6.2f} %")


if __name__ == "__main__":
    main()
