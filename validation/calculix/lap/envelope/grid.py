#!/usr/bin/env python3
"""The envelope grid: joint definitions, closed-form landmarks (from the frozen binary), load levels,
mesh sizes and the gen.py key=value overrides for each CalculiX run.

Usage: grid.py list | grid.py args NAME [variant]   (variant: c = coarse, f = mesh halved,
i = increments halved, s = stepped below F_1 too)"""
import json
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
MS = os.environ.get("MICROSLIP", os.path.join(HERE, "microslip"))
E1 = 70000.0
NU = 0.3
B = 25.0

# name: (KT, t1, t2, L, E2/E1, mu, P, role)   -- fixed BEFORE any run (hold-outs chosen up front)
JOINTS = {
    "C01": (1e2, 3.0, 0.9, 30.0, 1, 0.3, 10.0, "cal"),
    "C02": (1e2, 3.0, 6.0, 9.0, 3, 0.6, 50.0, "cal"),
    "C03": (1e2, 2.0, 2.0, 60.0, 1, 0.1, 5.0, "cal"),
    "C04": (1e2, 6.0, 4.0, 60.0, 3, 0.3, 15.0, "cal"),
    "C05": (1e3, 3.0, 2.0, 40.0, 1, 0.3, 10.0, "cal"),   # the bundled joint (FIRST-LOOK)
    "C06": (1e3, 2.0, 0.6, 60.0, 3, 0.6, 15.0, "cal"),
    "C07": (1e3, 6.0, 6.0, 18.0, 1, 0.1, 50.0, "cal"),
    "C08": (1e3, 3.0, 6.0, 30.0, 3, 0.3, 5.0, "cal"),
    "C09": (1e4, 3.0, 3.0, 30.0, 3, 0.1, 15.0, "cal"),
    "C10": (1e4, 2.0, 4.0, 60.0, 1, 0.3, 50.0, "cal"),
    "C11": (1e4, 6.0, 1.8, 18.0, 1, 0.6, 5.0, "cal"),
    "C12": (1e4, 3.0, 2.0, 9.0, 3, 0.3, 10.0, "cal"),
    "C13": (1e5, 2.0, 4.0, 60.0, 1, 0.1, 10.0, "cal"),
    "C14": (1e5, 3.0, 3.0, 9.0, 1, 0.6, 15.0, "cal"),
    "C15": (1e5, 6.0, 4.0, 60.0, 3, 0.3, 5.0, "cal"),
    "C16": (1e5, 3.0, 0.9, 30.0, 3, 0.1, 50.0, "cal"),
    "H1": (3e2, 3.0, 1.5, 45.0, 1, 0.2, 20.0, "holdout"),
    "H2": (3e3, 4.0, 5.0, 24.0, 3, 0.45, 8.0, "holdout"),
    "H3": (3e4, 2.5, 1.25, 50.0, 1, 0.4, 30.0, "holdout"),
    "H4": (5e4, 4.0, 6.0, 20.0, 3, 0.2, 12.0, "holdout"),
    "H5": (5e2, 2.5, 3.0, 12.5, 1, 0.5, 25.0, "holdout"),
    "H6": (2e4, 4.0, 2.0, 80.0, 3, 0.15, 6.0, "holdout"),
}


def params(name):
    KT, t1, t2, L, r, mu, P, role = JOINTS[name]
    return dict(KT=KT, t1=t1, t2=t2, L=L, E1=E1, E2=r * E1, mu=mu, P=P, b=B, nu=NU, role=role)


def closed(p, F, KT=None):
    args = [MS, "lap"]
    for k in ("L", "b", "t1", "t2", "E1", "E2", "P", "mu"):
        args += ["--set", f"{k}={p[k]!r}"]
    args += ["--set", f"KT={(KT if KT is not None else p['KT'])!r}", "--set", f"F={F!r}",
             "--format", "json"]
    d = json.loads(subprocess.run(args, capture_output=True, text=True, check=True).stdout)
    r = d["regularized"]
    return dict(Delta=r["Delta_mm"], a=r["a_mm"], d=r["d_mm"], regime=r["regime"], F1=d["F_1_N"],
                F2=d["F_2_N"], Fg=d["F_gross_N"], lam_inv=d["decay_length_mm"],
                first=d["first_slip_at"])


def k_eff(p):
    G1 = p["E1"] / (2 * (1 + p["nu"]))
    G2 = p["E2"] / (2 * (1 + p["nu"]))
    return 1 / (1 / p["KT"] + p["t1"] / 2 / (3 * G1) + p["t2"] / (3 * G2))


def levels(p):
    """0.5 F_1; (F_1 + F_2)/2 if F_2 - F_1 > 0.03 F_gross; (F_2 + F_gross)/2 if below 0.85 F_gross;
    0.9 F_gross; if every level is below F_1 (short joints), also (F_1 + F_gross)/2. Sorted,
    levels closer than 0.02 F_gross merged."""
    c = closed(p, 1.0)
    F1, F2, Fg = c["F1"], c["F2"], c["Fg"]
    lv = [("0.5F1", 0.5 * F1), ("0.9Fg", 0.9 * Fg)]
    if F2 - F1 > 0.03 * Fg:
        lv.append(("F1-F2", 0.5 * (F1 + F2)))
    if 0.5 * (F2 + Fg) < 0.85 * Fg:
        lv.append(("F2-Fg", 0.5 * (F2 + Fg)))
    if max(F for _, F in lv) < F1:
        lv.append(("F1-Fg", 0.5 * (F1 + Fg)))
    lv.sort(key=lambda q: q[1])
    out = [lv[0]]
    for q in lv[1:]:
        if q[1] - out[-1][1] > 0.02 * Fg:
            out.append(q)
    return out, c


def gen_args(name, variant="c"):
    p = params(name)
    lv, c = levels(p)
    lam_inv = c["lam_inv"]
    layer = min(p["t1"] / 2 / 4, p["t2"] / 4)
    he = min(2 / 3 * layer, lam_inv / 4)
    hm = min(8 / 3 * layer, lam_inv / 2)
    hx = 8 / 3 * layer
    n1 = n2 = 4
    ext = max(10.0, 2 * (p["t1"] / 2 + p["t2"]))
    dF = c["Fg"] / 60
    forces = [F for _, F in lv]
    incs = [1]
    prev = forces[0]
    for F in forces[1:]:
        # states below the closed form's F_1 are reached in one increment (FIRST-LOOK pitfall 2)
        incs.append(1 if F < c["F1"] else max(2, math.ceil((F - prev) / dF)))
        prev = F
    if variant == "x2":  # plates' extensions (Lc, Li) doubled
        ext = 2 * ext
    if variant == "f":
        he, hm, hx, n1, n2 = he / 2, hm / 2, hx / 2, 8, 8
    if variant == "s":   # every level beyond the first in fixed steps, even below F_1; none above 0.95 F_gross
        forces = [F for F in forces if F <= 0.95 * c["Fg"]]
        incs = [1] + [max(2, math.ceil((F - q) / dF)) for q, F in zip(forces[:-1], forces[1:])]
    if variant == "n0":  # nu = 0 in the deck (no Poisson expansion under the clamp)
        kv_nu = 0.0
    else:
        kv_nu = p["nu"]
    if variant == "i":
        incs = [1] + [2 * q for q in incs[1:]]
    kv = dict(L=p["L"], b=p["b"], t1=p["t1"], t2=p["t2"], E=p["E1"], E2=p["E2"], nu=kv_nu,
              Pr=p["P"], mu=p["mu"], KT=p["KT"], Lc=ext, Li=ext, n1=n1, n2=n2, he=he, hm=hm,
              hx=hx, forces=",".join(f"{F:.6f}" for F in forces),
              incs=",".join(map(str, incs)))
    return [f"{k}={v!r}" if not isinstance(v, str) else f"{k}={v}" for k, v in kv.items()]


if __name__ == "__main__":
    if sys.argv[1] == "list":
        for n in JOINTS:
            p = params(n)
            lv, c = levels(p)
            print(n, p["role"], f"1/lam={c['lam_inv']:.3f}", f"F1={c['F1']:.1f} F2={c['F2']:.1f} Fg={c['Fg']:.1f}",
                  c["first"], " ".join(f"{l}={F:.1f}" for l, F in lv), " ".join(gen_args(n)[-7:]))
    elif sys.argv[1] == "args":
        print(" ".join(gen_args(sys.argv[2], sys.argv[3] if len(sys.argv) > 3 else "c")))
