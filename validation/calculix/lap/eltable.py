#!/usr/bin/env python3
"""Elastic-regime table (every point below first sliding, one increment): usage eltable.py
COARSE:FINE ..."""
import sys
import tables as T

print("| K_T (MPa/mm) | 1/lambda (mm) | 1/(lambda t1) | F (N) | Delta closed (mm) | ccx coarse | ccx fine | "
      "rel. (fine) | mesh move | slip part ccx / closed | K_eff | rel. to closed at K_eff |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|")
for pair in sys.argv[1:]:
    c, f = pair.split(":")
    rc, rf = T.load(c), T.load(f)
    P = rf["params"]
    F = rf["rows"][0]["F"]
    cl = T.closed(P["KT"], F)
    Dc, Df = rc["rows"][0]["Delta_mean"], rf["rows"][0]["Delta_mean"]
    bonded = F * P["L"] / (P["b"] * (P["E"] * P["t1"] + 2 * P["E"] * P["t2"]))
    ke = round(T.k_eff(P), 3)
    ce = T.closed(ke, F)
    print(f"| {P['KT']:g} | {cl['lam']:.3f} | {cl['lam'] / P['t1']:.3f} | {F:g} | {cl['Delta']:.6g} | {Dc:.6g} | "
          f"{Df:.6g} | {100 * (Df / cl['Delta'] - 1):+.2f} % | {100 * (Df / Dc - 1):+.3f} % | "
          f"{(Df - bonded) / (cl['Delta'] - bonded):.3f} | {ke:g} | {100 * (Df / ce['Delta'] - 1):+.2f} % |")
