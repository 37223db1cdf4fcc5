#!/usr/bin/env python3
"""Closed-form-only quantities per case (no CalculiX): the K_eff correction's size on Delta,
r_keff = Delta_cf(K_eff)/Delta_cf(K_T) - 1, and the dimensionless parameters."""
import grid
for n in grid.JOINTS:
    p = grid.params(n)
    lv, c = grid.levels(p)
    ke = grid.k_eff(p)
    lam = 1 / c["lam_inv"]
    out = []
    for lab, F in lv:
        a = grid.closed(p, F)["Delta"]
        b = grid.closed(p, F, KT=ke)["Delta"]
        out.append(f"{lab}:{100*(b/a-1):+.2f}%")
    print(n, p["role"], f"lam_t1={lam*p['t1']:.3f} lam_h={lam*(p['t1']/2+p['t2']):.3f} lamL={lam*p['L']:.2f} eps={p['KT']/ke-1:.3f}", " ".join(out))
