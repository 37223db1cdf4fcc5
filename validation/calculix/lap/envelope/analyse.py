#!/usr/bin/env python3
"""Collect runs/NAME_c/post.json for every joint of grid.py, compare with the closed form
(frozen binary) at K_T and at K_eff, write cases.json and print the per-case table.
Usage: analyse.py [variant]   (default c)"""
import json
import math
import os
import sys

import grid

HERE = os.path.dirname(os.path.abspath(__file__))


def case_rows(name, var="c"):
    path = os.path.join(HERE, "runs", f"{name}_{var}", "post.json")
    if not os.path.exists(path):
        return None
    r = json.load(open(path))
    p = grid.params(name)
    lv, c0 = grid.levels(p)
    ke = grid.k_eff(p)
    G1 = p["E1"] / (2 * (1 + p["nu"]))
    G2 = p["E2"] / (2 * (1 + p["nu"]))
    lam = 1 / c0["lam_inv"]
    k1 = p["E1"] * p["t1"]
    K2 = 2 * p["E2"] * p["t2"]
    eps = p["KT"] / ke - 1
    dimless = dict(lam_t1=lam * p["t1"], lam_h=lam * (p["t1"] / 2 + p["t2"]), t2_t1=p["t2"] / p["t1"],
                   E2t2_E1t1=p["E2"] * p["t2"] / (p["E1"] * p["t1"]), L_t1=p["L"] / p["t1"],
                   lam_L=lam * p["L"], mu=p["mu"], muP_E1=p["mu"] * p["P"] / p["E1"], eps=eps,
                   K2_k1=K2 / k1)
    rows = []
    for (lab, F), q in zip(lv, r["rows"]):
        assert abs(q["F"] - F) < 1e-3 * F, (name, q["F"], F)
        cf = grid.closed(p, F)
        ce = grid.closed(p, F, KT=ke)
        D = q["Delta_mean"]
        bonded = F * p["L"] / (p["b"] * (k1 + K2))
        rows.append(dict(
            name=name, variant=var, role=p["role"], level=lab, F=F, F_over_Fg=F / c0["Fg"],
            regime=cf["regime"], Delta_ccx=D, Delta_cf=cf["Delta"], err=D / cf["Delta"] - 1,
            Delta_cf_keff=ce["Delta"], err_keff=D / ce["Delta"] - 1,
            interface_share=(cf["Delta"] - bonded) / cf["Delta"],
            err_iface=(D - bonded) / (cf["Delta"] - bonded) - 1,
            a_ccx=q["a_s"], d_ccx=q["d_s"], a_p=q["a_p"], d_p=q["d_p"], a_tau=q["a_tau"], d_tau=q["d_tau"],
            a_cf=cf["a"], d_cf=cf["d"], a_keff=ce["a"], d_keff=ce["d"], p0=q["p0"], pL=q["pL"],
            K_eff=ke, params={k: v for k, v in p.items() if k != "role"},
            F1=c0["F1"], F2=c0["F2"], Fg=c0["Fg"], first_slip=c0["first"], **dimless))
    return rows


def main():
    var = sys.argv[1] if len(sys.argv) > 1 else "c"
    allrows = []
    for n in grid.JOINTS:
        rr = case_rows(n, var)
        if rr:
            allrows += rr
    if var == "c":
        out = [dict(q) for q in allrows]
        try:
            import envelope
            cu, ck = [1.0, 2.0, 0.36, 0.013], [0.0, 1.9, 0.32, 0.013]
            for q in out:
                f = envelope.feats(q)
                q.update(r_keff=f["r"], m=f["m"], q_p=f["qp"], b=f["b"], in_domain=envelope.in_domain(q),
                         B=envelope.bound(cu, f), B_k=envelope.bound(ck, f),
                         B_w=envelope.WIDEN * envelope.bound(cu, f), B_kw=envelope.WIDEN * envelope.bound(ck, f))
        except Exception as e:  # first pass: envelope.py reads cases.json
            print("note: bounds not added:", e, file=sys.stderr)
        # control runs (mesh halved f, increments halved i, nu = 0 n0, stepped s, extensions x2)
        for n in grid.JOINTS:
            for v in ("f", "i", "n0", "s", "x2"):
                rr = case_rows(n, v)
                for q in rr or []:
                    q["role"] = "control"
                    if v == "n0":
                        q["note"] = "deck nu = 0; K_eff and err_keff still use nu = 0.3"
                    out.append(q)
        json.dump(out, open(os.path.join(HERE, "cases.json"), "w"), indent=1)
    print("| case | role | level | F (N) | F/Fg | regime (cf) | Delta ccx (mm) | Delta cf (mm) | err | err K_eff | a ccx/cf/K_eff | d ccx/cf/K_eff | p(0), p(L) |")
    print("|" + "---|" * 13)
    for q in allrows:
        print(f"| {q['name']} | {q['role']} | {q['level']} | {q['F']:.1f} | {q['F_over_Fg']:.3f} | {q['regime']} | "
              f"{q['Delta_ccx']:.6g} | {q['Delta_cf']:.6g} | {100*q['err']:+.2f} % | {100*q['err_keff']:+.2f} % | "
              f"{q['a_ccx']:.2f} / {q['a_cf']:.2f} / {q['a_keff']:.2f} | {q['d_ccx']:.2f} / {q['d_cf']:.2f} / {q['d_keff']:.2f} | "
              f"{q['p0']:.1f}, {q['pL']:.1f} |")


if __name__ == "__main__":
    main()
