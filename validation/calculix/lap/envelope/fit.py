#!/usr/bin/env python3
"""Fit a conservative bound B = c_k |r_keff| + c_m m + c_b beta >= |err| on the calibration cases
(linear programme: minimise the sum of B over the calibration cases subject to B_i >= |err_i|,
c >= 0), then check the hold-out cases.

Features (all from the joint's parameters and the closed form; no CalculiX):
  r_keff = Delta_cf(K_eff)/Delta_cf(K_T) - 1   the through-thickness shear correction on Delta
  m      = nu K_T |1/E1 - 1/E2| tanh(lambda L/2) / (lambda mu)   clamping (Poisson) prestress / mu P
  beta   = mu (t1/2 + t2) / L                  cover bending (eccentric interface shear) share
Usage: fit.py [--exclude NAME,...]"""
import json
import math
import os
import sys

import numpy as np
from scipy.optimize import linprog

HERE = os.path.dirname(os.path.abspath(__file__))


def features(q):
    p = q["params"]
    lam = q["lam_L"] / p["L"]
    r = q["Delta_cf_keff"] / q["Delta_cf"] - 1
    m = p["nu"] * p["KT"] * abs(1 / p["E1"] - 1 / p["E2"]) * math.tanh(lam * p["L"] / 2) / (lam * p["mu"])
    beta = p["mu"] * (p["t1"] / 2 + p["t2"]) / p["L"]
    return np.array([abs(r), m, beta])


def fit(rows, cols=(0, 1, 2)):
    X = np.array([features(q)[list(cols)] for q in rows])
    y = np.array([abs(q["err"]) for q in rows])
    res = linprog(c=X.sum(axis=0), A_ub=-X, b_ub=-y, bounds=[(0, None)] * X.shape[1], method="highs")
    return res.x


if __name__ == "__main__":
    rows = json.load(open(os.path.join(HERE, "cases.json")))
    excl = set()
    if "--exclude" in sys.argv:
        excl = set(sys.argv[sys.argv.index("--exclude") + 1].split(","))
    cal = [q for q in rows if q["role"] == "cal" and q["name"] not in excl]
    ho = [q for q in rows if q["role"] == "holdout"]
    for cols in ((0, 1, 2),):
        c = fit(cal, cols)
        print("coefficients", cols, c)
        for q in cal + ho:
            f = features(q)[list(cols)]
            B = float(f @ c)
            print(f"{q['name']:4s} {q['role']:8s} {q['level']:6s} err {100*q['err']:+7.2f} %  err_keff {100*q['err_keff']:+7.2f} %  "
                  f"B {100*B:6.2f} %  r {100*f[0]:6.2f} m {f[1]:.3f} beta {f[2]:.3f}  {'OK' if abs(q['err']) <= B + 1e-12 else 'EXCEEDS'}")
