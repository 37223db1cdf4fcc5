#!/usr/bin/env python3
"""Read NAME.dat / NAME.frd / NAME.json of a gen.py deck; print per force Delta (thickness mean,
mid-plane, interface), and the sliding zones a (from x = 0), d (from x = L).

Delta is zeroed at the end of step 1 (the clamping pressure alone stretches both plates by
nu P / E through Poisson: ~1.7e-3 mm over the overlap), as an extensometer zeroed after clamping.

Sliding zones, two readings:
  a_p, d_p:     where K_T |slip| >= mu p_local (p_local = CPRESS at the cover node), interpolated;
  a_tau, d_tau: where CalculiX's contact shear at the slave (cover) nodes reaches mu * p_local
                (|CSHEAR| >= (1 - 1e-3) mu CPRESS), contiguous from each end;
  a_s, d_s:     where K_T * slip >= mu P with slip = u_inner - u_cover at facing interface nodes
                (measured from the end of step 1), contiguous from each end, linear interpolation
                at the crossing (the closed form's own definition).
Usage: post.py NAME [--json]
"""
import json
import sys

import numpy as np


def read_dat(path):
    out = {}  # time -> set -> list of (node, ux, uy)
    cur = None
    with open(path) as f:
        for line in f:
            if "displacements" in line and "for set" in line:
                w = line.split()
                s = w[w.index("set") + 1]
                t = float(w[-1])
                cur = out.setdefault(t, {}).setdefault(s, [])
            elif line.strip() == "":
                continue
            elif cur is not None:
                w = line.split()
                try:
                    cur.append((int(w[0]), float(w[1]), float(w[2])))
                except (ValueError, IndexError):
                    cur = None
    return out


def read_frd_contact(path, wanted):
    """time -> node -> (copen, cslip1, cslip2, cpress, cshear1, cshear2) for nodes in wanted."""
    out = {}
    t = None
    in_contact = False
    with open(path) as f:
        for line in f:
            if line.startswith("  100CL"):
                t = float(line[12:25])
                in_contact = False
            elif line.startswith(" -4  CONTACT"):
                in_contact = True
                cur = out.setdefault(t, {})
            elif line.startswith(" -4"):
                in_contact = False
            elif in_contact and line.startswith(" -1"):
                n = int(line[3:13])
                if n in wanted:
                    vals = [float(line[13 + 12 * k:25 + 12 * k]) for k in range(6)]
                    cur[n] = vals
            elif line.startswith(" -3"):
                in_contact = False
    return out


def thickness_mean(ys, us):
    """Simpson per quadratic element (nodes corner, mid, corner, ...)."""
    tot = 0.0
    for k in range(0, len(ys) - 2, 2):
        h = ys[k + 2] - ys[k]
        tot += h / 6 * (us[k] + 4 * us[k + 1] + us[k + 2])
    return tot / (ys[-1] - ys[0])


def zone_from(xs, flag, from_end):
    """Length of the contiguous run of True from x = xs[0] (from_end False) or xs[-1]."""
    idx = range(len(xs)) if not from_end else range(len(xs) - 1, -1, -1)
    last = None
    for i in idx:
        if flag[i]:
            last = i
        else:
            break
    if last is None:
        return 0.0
    return abs(xs[last] - (xs[0] if not from_end else xs[-1]))


def zone_interp(xs, g, from_end):
    """g = K_T s / (mu P) - 1: contiguous g >= 0 from the end, interpolated at the crossing."""
    n = len(xs)
    order = list(range(n)) if not from_end else list(range(n - 1, -1, -1))
    x0 = xs[order[0]]
    if g[order[0]] < 0:
        return 0.0
    for a, b in zip(order[:-1], order[1:]):
        if g[b] < 0:
            xc = xs[a] + (xs[b] - xs[a]) * g[a] / (g[a] - g[b])
            return abs(xc - x0)
    return abs(xs[order[-1]] - x0)


def analyse(name):
    meta = json.load(open(name + ".json"))
    P = meta["params"]
    dat = read_dat(name + ".dat")
    times = sorted(dat)
    cface = meta["CFACE"]
    iface = meta["IFACE"]
    wanted = {n for n, _ in cface}
    frd = read_frd_contact(name + ".frd", wanted)

    def delta_parts(t):
        d = dat[t]
        il = {n: ux for n, ux, _ in d["IL"]}
        c0 = {n: ux for n, ux, _ in d["C0"]}
        yi = [y for _, y in meta["IL"]]
        ui = [il[n] for n, _ in meta["IL"]]
        yc = [y for _, y in meta["C0"]]
        uc = [c0[n] for n, _ in meta["C0"]]
        mean = thickness_mean(yi, ui) - thickness_mean(yc, uc)
        mid = ui[0] - uc[len(uc) // 2]          # inner mid-plane (y = 0), cover mid-thickness
        face = ui[-1] - uc[0]                   # both at the interface y = t1/2
        return np.array([mean, mid, face])

    def slip(t):
        d = dat[t]
        ui = {n: ux for n, ux, _ in d["IFACE"]}
        uc = {n: ux for n, ux, _ in d["CFACE"]}
        return np.array([ui[n] for n, _ in iface]) - np.array([uc[n] for n, _ in cface])

    xs = np.array([x for _, x in iface])
    t0 = times[0]
    base = delta_parts(t0)
    s0 = slip(t0)
    rows = []
    forces = meta["forces"]
    for k, t in enumerate(times[1:]):
        F = forces[k]
        dp = delta_parts(t) - base
        s = slip(t) - s0
        g = P["KT"] * s / (P["mu"] * P["Pr"]) - 1
        a_s = zone_interp(xs, g, False)
        d_s = zone_interp(xs, g, True)
        c = frd.get(t, {})
        a_tau = d_tau = a_p = d_p = p0 = pL = pint = float("nan")
        if c:
            xc = [x for _, x in cface]
            press = np.array([c[n][3] for n, _ in cface])
            shear = np.array([np.hypot(c[n][4], c[n][5]) for n, _ in cface])
            sat = shear >= (1 - 1e-3) * P["mu"] * press
            a_tau = zone_from(xc, sat, False)
            d_tau = zone_from(xc, sat, True)
            gp = P["KT"] * np.abs(s) / (P["mu"] * press) - 1
            a_p = zone_interp(xs, gp, False)
            d_p = zone_interp(xs, gp, True)
            p0, pL = press[0], press[-1]
            pint = float(np.trapezoid(press, xc) / (P["Pr"] * P["L"]))
        rows.append(dict(F=F, Delta_mean=dp[0], Delta_mid=dp[1], Delta_face=dp[2],
                         Delta_raw_mean=(dp + base)[0], a_s=a_s, d_s=d_s, a_tau=a_tau, d_tau=d_tau,
                         a_p=a_p, d_p=d_p, p0=p0, pL=pL, pint=pint))
    return dict(name=name, params=P, n_elements=meta["n_elements"], step1_Delta=base.tolist(),
                rows=rows)


if __name__ == "__main__":
    r = analyse(sys.argv[1])
    if "--json" in sys.argv:
        print(json.dumps(r))
    else:
        print(r["name"], r["n_elements"], "elements; step-1 Delta (mean, mid, face):",
              ["%.4g" % v for v in r["step1_Delta"]])
        for row in r["rows"]:
            print("F %6.0f  Delta mean %.6e mid %.6e face %.6e  a_s %.3f d_s %.3f  a_p %.3f d_p %.3f"
                  "  a_tau %.3f d_tau %.3f  p(0) %.2f p(L) %.2f  int(p)/(P L) %.4f"
                  % (row["F"], row["Delta_mean"], row["Delta_mid"], row["Delta_face"],
                     row["a_s"], row["d_s"], row["a_p"], row["d_p"], row["a_tau"], row["d_tau"],
                     row["p0"], row["pL"], row["pint"]))
