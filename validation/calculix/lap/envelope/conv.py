#!/usr/bin/env python3
"""Convergence spot checks: Delta and zones of NAME_f (mesh halved) and NAME_i (increments halved)
against NAME_c.  Usage: conv.py NAME ..."""
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def load(run):
    p = os.path.join(HERE, "runs", run, "post.json")
    return json.load(open(p)) if os.path.exists(p) else None


def wall(run):
    for line in open(os.path.join(HERE, "runs", run, "gen.txt")):
        if line.startswith("wall"):
            return line.split()[1]
        if "elements" in line:
            ne = line.split(":")[1].split()[0]
    return "?"


print("| joint | change | F (N) | Delta coarse (mm) | Delta changed (mm) | move | a_s, d_s coarse | a_s, d_s changed |")
print("|---|---|---|---|---|---|---|---|")
for n in sys.argv[1:]:
    c = load(n + "_c")
    for v, lab in (("f", "mesh halved"), ("i", "increments halved"), ("x2", "extensions Lc, Li doubled")):
        o = load(f"{n}_{v}")
        if c is None or o is None:
            continue
        for qc, qo in zip(c["rows"], o["rows"]):
            print(f"| {n} | {lab} ({c['n_elements']} -> {o['n_elements']} el.) | {qc['F']:.1f} | {qc['Delta_mean']:.7g} | "
                  f"{qo['Delta_mean']:.7g} | {100 * (qo['Delta_mean'] / qc['Delta_mean'] - 1):+.3f} % | "
                  f"{qc['a_s']:.2f}, {qc['d_s']:.2f} | {qo['a_s']:.2f}, {qo['d_s']:.2f} |")
