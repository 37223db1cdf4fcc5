"""Second independent check (finite differences, active set) of the push-out's regularized Delta
and F_1: s'' = w tau(s) (1/EsAs + 1/EhAh), s'(0) = -F/EsAs, s'(L) = F/EhAh, tau = min(KT s, mu p)."""
import json, math, subprocess, sys
import numpy as np
sys.path.insert(0, __import__("os").path.dirname(__file__))
from indep import lame, cases, KEYS, coulomb

def thomas(a, b, c, d):
    n = len(d); cp = np.zeros(n); dp = np.zeros(n)
    cp[0] = c[0] / b[0]; dp[0] = d[0] / b[0]
    for i in range(1, n):
        m = b[i] - a[i] * cp[i - 1]
        cp[i] = c[i] / m if i < n - 1 else 0.0
        dp[i] = (d[i] - a[i] * dp[i - 1]) / m
    x = np.zeros(n); x[-1] = dp[-1]
    for i in range(n - 2, -1, -1):
        x[i] = dp[i] - cp[i] * x[i + 1]
    return x

def fd(g, F, KT, n=20000, cap=True):
    r, ri, ro, L, Es, nus, Eh, nuh, delta, mu = g
    p = lame(r, ri, ro, Es, nus, Eh, nuh, delta)
    EsAs = Es * math.pi * (r**2 - ri**2); EhAh = Eh * math.pi * (ro**2 - r**2)
    w = 2 * math.pi * r; c = w * (1 / EsAs + 1 / EhAh); tmax = mu * p
    h = L / n; N = n + 1
    plastic = np.zeros(N, dtype=bool)
    for _ in range(100):
        a = np.full(N, 1 / h**2); cc = np.full(N, 1 / h**2)
        b = np.where(plastic, -2 / h**2, -2 / h**2 - c * KT)
        d = np.where(plastic, c * tmax, 0.0)
        # Neumann by ghost nodes: s_{-1} = s_1 - 2 h s'(0); s_{N} = s_{N-2} + 2 h s'(L)
        cc[0] = 2 / h**2; d[0] += 2 * (-F / EsAs) / h  # from (s1 - 2s0 + s_-1)/h^2
        a[-1] = 2 / h**2; d[-1] -= 2 * (F / EhAh) / h
        s = thomas(a, b, cc, d)
        new = (KT * s > tmax) if cap else np.zeros(N, dtype=bool)
        if (new == plastic).all():
            break
        plastic = new
    tau = np.where(plastic, tmax, KT * s)
    q = w * tau
    Nh = np.concatenate([[0], np.cumsum(0.5 * (q[1:] + q[:-1]) * h)])
    ih = np.sum(0.5 * (Nh[1:] + Nh[:-1]) * h)
    return s, s[0] + ih / EhAh, tmax, p, mu * p * w * L

worst = 0
for name, cse in cases.items():
    g, KT = cse[:10], cse[10]
    s1, _, tmax, p, gross = fd(g, 1.0, KT, cap=False)
    F1 = tmax / (KT * s1.max())
    for frac in (0.3, 0.8):
        F = frac * gross
        _, d_reg, *_ = fd(g, F, KT)
        sets = sum((["--set", f"{k}={v!r}"] for k, v in zip(KEYS + ["KT", "F"], cse[:10] + [KT, F])), [])
        j = json.loads(subprocess.run([sys.argv[1], "pressfit", "--preset", "pressfit-ccx98", *sets, "--format", "json"], capture_output=True, text=True).stdout)
        e = [abs(j["regularized"]["Delta_mm"] / d_reg - 1), abs(j["F_1_N"] / F1 - 1), abs(j["coulomb"]["Delta_mm"] / coulomb(g, F) - 1)]
        worst = max(worst, *e)
        print(f"{name:11s} {frac}  F_1 {F1:.8g} ({j['F_1_N']:.8g}, {j['first_slip_at']})  Delta reg {d_reg:.8g} ({j['regularized']['Delta_mm']:.8g})  rel {max(e):.1e}")
print("worst", worst)
