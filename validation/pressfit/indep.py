"""Independent check of the press fit's push-out (no code shared with microslip): Lamé's p by
hand, and the shear-lag ODE s'' = 2 pi r tau(s) (1/EsAs + 1/EhAh) integrated by RK4 and shot on
s(0), tau = min(K_T s, mu p). Compared with `microslip pressfit --format json`."""
import json, math, subprocess, sys

def lame(r, ri, ro, Es, nus, Eh, nuh, delta):
    hub = ((ro**2 + r**2) / (ro**2 - r**2) + nuh) / Eh
    shaft = ((r**2 + ri**2) / (r**2 - ri**2) - nus) / Es
    return delta / (r * (hub + shaft))

def solve(g, F, KT, n=40000):
    r, ri, ro, L, Es, nus, Eh, nuh, delta, mu = g
    p = lame(r, ri, ro, Es, nus, Eh, nuh, delta)
    EsAs = Es * math.pi * (r**2 - ri**2)
    EhAh = Eh * math.pi * (ro**2 - r**2)
    w = 2 * math.pi * r
    tmax = mu * p
    tau = (lambda s: max(-tmax, min(KT * s, tmax))) if KT else None
    def shoot(s0):
        h = L / n
        # y = s, s', Nh, int Nh
        y = [s0, -F / EsAs, 0.0, 0.0]
        def f(y):
            t = tau(y[0])
            return [y[1], w * t * (1 / EsAs + 1 / EhAh), w * t, y[2]]
        for _ in range(n):
            k1 = f(y)
            k2 = f([y[i] + 0.5 * h * k1[i] for i in range(4)])
            k3 = f([y[i] + 0.5 * h * k2[i] for i in range(4)])
            k4 = f([y[i] + h * k3[i] for i in range(4)])
            y = [y[i] + h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]) for i in range(4)]
        return y
    lo, hi = 0.0, 1.0
    while shoot(hi)[1] < F / EhAh:
        hi *= 2
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if shoot(mid)[1] < F / EhAh:
            lo = mid
        else:
            hi = mid
    y = shoot(0.5 * (lo + hi))
    delta_resp = 0.5 * (lo + hi) + y[3] / EhAh
    return p, mu * p * w * L, delta_resp

def coulomb(g, F):
    r, ri, ro, L, Es, nus, Eh, nuh, delta, mu = g
    p = lame(r, ri, ro, Es, nus, Eh, nuh, delta)
    EsAs = Es * math.pi * (r**2 - ri**2)
    EhAh = Eh * math.pi * (ro**2 - r**2)
    q = mu * p * 2 * math.pi * r          # N/mm in the sliding zones
    ks = EsAs / (EsAs + EhAh)
    a, d = F * (1 - ks) / q, F * ks / q   # sliding lengths from x = 0 and x = L
    # N_s(x): F - q x on [0, a], F ks on the stick, q (L - x) on [L - d, L]; N_h = F - N_s.
    # s(x) = 0 on the stick; s' = -N_s/EsAs + N_h/EhAh; s(0) = -int_0^a s'.
    sp = lambda x: -(F - q * x) / EsAs + (q * x) / EhAh
    s0 = -(-(F * a - q * a * a / 2) / EsAs + (q * a * a / 2) / EhAh)
    # int_0^L N_h: [0,a]: q x; stick: F(1-ks); [L-d, L]: F - q (L - x)
    ih = q * a * a / 2 + F * (1 - ks) * (L - a - d) + (F * d - q * d * d / 2)
    return s0 + ih / EhAh

KEYS = "r ri ro L Es nus Eh nuh delta mu".split()
cases = {
    "ccx98": [20, 10, 30, 17.7332, 210000, .3, 210000, .3, .0025, .1, 1e4],
    "short-soft": [10, 0, 14, 5, 70000, .33, 70000, .33, .01, .15, 500],
    "long-stiff": [25, 0, 60, 150, 210000, .3, 210000, .3, .02, .12, 5e5],
    "thin-hub": [30, 20, 33, 40, 210000, .29, 110000, .34, .015, .2, 2e4],
    "alu-hub": [15, 5, 40, 30, 210000, .3, 70000, .33, .008, .1, 3e3],
    "big": [100, 60, 160, 120, 200000, .3, 200000, .3, .06, .15, 1e5],
}
if __name__ == "__main__":
    worst = 0
    for name, c in cases.items():
        g, KT = c[:10], c[10]
        _, gross, _ = solve(g, 1.0, KT, n=10)
        for frac in (0.3, 0.8):
            F = frac * gross
            p, gross, d_reg = solve(g, F, KT)
            d_c = coulomb(g, F)
            sets = sum((["--set", f"{k}={v!r}"] for k, v in zip(KEYS + ["KT", "F"], c[:10] + [KT, F])), [])
            out = subprocess.run([sys.argv[1], "pressfit", "--preset", "pressfit-ccx98", *sets, "--format", "json"],
                                 capture_output=True, text=True)
            if out.returncode:
                print(name, frac, out.stderr.strip()); continue
            j = json.loads(out.stdout)
            errs = [abs(j["p_MPa"] / p - 1), abs(j["F_gross_N"] / gross - 1),
                    abs(j["regularized"]["Delta_mm"] / d_reg - 1), abs(j["coulomb"]["Delta_mm"] / d_c - 1)]
            worst = max(worst, *errs)
            print(f"{name:11s} {frac} p {p:.6g} F_gross {gross:.6g} Delta reg {d_reg:.8g} coul {d_c:.8g}  rel err {max(errs):.1e}")
    print("worst", worst)
