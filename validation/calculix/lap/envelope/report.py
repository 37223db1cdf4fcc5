#!/usr/bin/env python3
"""Markdown tables for ENVELOPE.md from cases.json: the grid and the per-case table."""
import json
import math
import os

import grid
from fit import features

HERE = os.path.dirname(os.path.abspath(__file__))
rows = json.load(open(os.path.join(HERE, "cases.json")))

print("| joint | role | K_T (MPa/mm) | t1 | t2 | L | E2/E1 | mu | P (MPa) | 1/lambda (mm) | lambda t1 | lambda (t1/2+t2) | t2/t1 | E2t2/(E1t1) | L/t1 | lambda L | eps = K_T/K_eff - 1 | m (clamp prestress) | beta = mu (t1/2+t2)/L | F_1, F_2, F_gross (N) | first slip |")
print("|" + "---|" * 21)
seen = set()
for q in rows:
    if q["name"] in seen:
        continue
    seen.add(q["name"])
    p = q["params"]
    f = features(q)
    print(f"| {q['name']} | {q['role']} | {p['KT']:g} | {p['t1']:g} | {p['t2']:g} | {p['L']:g} | {p['E2']/p['E1']:g} | {p['mu']:g} | {p['P']:g} | "
          f"{p['L']/q['lam_L']:.3f} | {q['lam_t1']:.3f} | {q['lam_h']:.3f} | {q['t2_t1']:.2f} | {q['E2t2_E1t1']:.2f} | {q['L_t1']:.1f} | {q['lam_L']:.2f} | "
          f"{q['eps']:.3f} | {f[1]:.3f} | {f[2]:.3f} | {q['F1']:.0f}, {q['F2']:.0f}, {q['Fg']:.0f} | {q['first_slip']} |")
print()
print("| case | level | F (N) | F/F_gross | regime (closed form) | Delta ccx (mm) | Delta cf (mm) | err | Delta cf at K_eff (mm) | err at K_eff | r_keff | a ccx (a_s) / cf / K_eff (mm) | d ccx (d_s) / cf / K_eff (mm) | a-a_cf, d-d_cf (mm) | p(0), p(L) ccx (MPa) |")
print("|" + "---|" * 15)
for q in rows:
    f = features(q)
    print(f"| {q['name']} | {q['level']} | {q['F']:.1f} | {q['F_over_Fg']:.3f} | {q['regime']} | {q['Delta_ccx']:.6g} | {q['Delta_cf']:.6g} | "
          f"{100*q['err']:+.2f} % | {q['Delta_cf_keff']:.6g} | {100*q['err_keff']:+.2f} % | {100*f[0]:.2f} % | "
          f"{q['a_ccx']:.2f} / {q['a_cf']:.2f} / {q['a_keff']:.2f} | {q['d_ccx']:.2f} / {q['d_cf']:.2f} / {q['d_keff']:.2f} | "
          f"{q['a_ccx']-q['a_cf']:+.2f}, {q['d_ccx']-q['d_cf']:+.2f} | {q['p0']:.1f}, {q['pL']:.1f} |")
