#!/usr/bin/env python3
"""Collect runs/*/post.json, compare with the closed form (microslip lap, read-only use of the
project's binary) and print markdown tables.  Usage: tables.py RUN [RUN ...]"""
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
MS = os.environ.get("MICROSLIP", os.path.join(HERE, "../../../target/debug/microslip"))
_cache = {}


def closed(KT, F):
    key = (KT, F)
    if key not in _cache:
        out = subprocess.run([MS, "lap", "--set", f"F={F}", "--set", f"KT={KT}", "--format", "json"],
                             capture_output=True, text=True, check=True).stdout
        d = json.loads(out)
        r = d["regularized"]
        _cache[key] = dict(Delta=r["Delta_mm"], a=r["a_mm"], d=r["d_mm"], regime=r["regime"],
                           F1=d["F_1_N"], F2=d["F_2_N"], lam=d["decay_length_mm"],
                           coulomb=d["coulomb"]["Delta_mm"])
    return _cache[key]


def k_eff(P):
    """Shear-corrected stick slope: K_T in series with each plate's through-thickness shear
    compliance t/(3G) (linear shear from the interface to a free face / symmetry plane, read at the
    thickness mean): 1/K_eff = 1/K_T + (t1/2 + t2)/(3G), G = E/(2(1+nu))."""
    G = P["E"] / (2 * (1 + P["nu"]))
    return 1 / (1 / P["KT"] + (P["t1"] / 2 + P["t2"]) / (3 * G))


def load(name):
    return json.load(open(os.path.join(HERE, "runs", name, "post.json")))


def table(names):
    runs = [load(n) for n in names]
    KT = runs[0]["params"]["KT"]
    print(f"\nK_T = {KT:g} MPa/mm, 1/lambda = {closed(KT, 1000)['lam']:.3f} mm, "
          f"F_1 = {closed(KT, 1000)['F1']:.0f} N, F_2 = {closed(KT, 1000)['F2']:.0f} N\n")
    ke = round(k_eff(runs[0]["params"]), 3)
    print(f"shear-corrected K_eff = {ke:g} MPa/mm (1/lambda_eff = {closed(ke, 1000)['lam']:.3f} mm)\n")
    hdr = "| F (N) | Delta closed (mm) | " + " | ".join(
        f"{r['name']} Delta (mm) | rel." for r in runs) + " | closed at K_eff | last run rel. to it | a, d closed at K_eff |"
    print(hdr)
    print("|" + "---|" * (5 + 2 * len(runs)))
    for k, row in enumerate(runs[0]["rows"]):
        F = row["F"]
        c = closed(KT, F)
        cells = [f"{F:.0f}", f"{c['Delta']:.6g}"]
        for r in runs:
            D = r["rows"][k]["Delta_mean"]
            cells += [f"{D:.6g}", f"{100 * (D / c['Delta'] - 1):+.2f} %"]
        ce = closed(ke, F)
        cells += [f"{ce['Delta']:.6g}", f"{100 * (D / ce['Delta'] - 1):+.2f} %", f"{ce['a']:.2f}, {ce['d']:.2f}"]
        print("| " + " | ".join(cells) + " |")
    print()
    print("| F (N) | a closed | d closed | " + " | ".join(
        f"{r['name']} a_s / a_p / a_tau | d_s / d_p / d_tau" for r in runs) + " |")
    print("|" + "---|" * (3 + 2 * len(runs)))
    for k, row in enumerate(runs[0]["rows"]):
        F = row["F"]
        c = closed(KT, F)
        cells = [f"{F:.0f}", f"{c['a']:.2f}", f"{c['d']:.2f}"]
        for r in runs:
            q = r["rows"][k]
            cells += [f"{q['a_s']:.2f} / {q['a_p']:.2f} / {q['a_tau']:.2f}",
                      f"{q['d_s']:.2f} / {q['d_p']:.2f} / {q['d_tau']:.2f}"]
        print("| " + " | ".join(cells) + " |")


def moves(pairs):
    print("\n| change | F (N) | Delta before (mm) | Delta after (mm) | move |")
    print("|---|---|---|---|---|")
    for a, b, label in pairs:
        ra, rb = load(a), load(b)
        for qa, qb in zip(ra["rows"], rb["rows"]):
            print(f"| {label} ({a} -> {b}) | {qa['F']:.0f} | {qa['Delta_mean']:.6g} | "
                  f"{qb['Delta_mean']:.6g} | {100 * (qb['Delta_mean'] / qa['Delta_mean'] - 1):+.3f} % |")


def detail(name):
    r = load(name)
    KT = r["params"]["KT"]
    print(f"\n{name}: step-1 Delta (mean, mid, face) = " +
          ", ".join(f"{v:.4g}" for v in r["step1_Delta"]))
    print("| F | closed | mean | mid-plane | interface | p(0) | p(L) |")
    print("|---|---|---|---|---|---|---|")
    for q in r["rows"]:
        c = closed(KT, q["F"])["Delta"]
        print(f"| {q['F']:.0f} | {c:.6g} | {100 * (q['Delta_mean'] / c - 1):+.2f} % | "
              f"{100 * (q['Delta_mid'] / c - 1):+.2f} % | {100 * (q['Delta_face'] / c - 1):+.2f} % | "
              f"{q['p0']:.2f} | {q['pL']:.2f} |")


if __name__ == "__main__":
    args = sys.argv[1:]
    if args[0] == "moves":
        it = iter(args[1:])
        moves([(a, b, l) for a, b, l in zip(it, it, it)])
    elif args[0] == "detail":
        for n in args[1:]:
            detail(n)
    else:
        table(args)
