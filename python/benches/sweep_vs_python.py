"""BENCHMARKS.md, "Python": the regularized w(L) of the paper's twin beams at 1e6 tip forces,
computed four ways in one run, each timed once:

1. ``TwinBeams.sweep(F=...)`` (this package);
2. the same closed form (docs/theory.md (B3)-(B11)) written here in NumPy, vectorized, its root
   X found by vectorized bisection;
3. the same closed form as a pure-Python loop, X by ``scipy.optimize.brentq``;
4. the CLI: ``microslip sweep --preset paper-beams --from 0 --to 240 --points 1000000 --format csv``.

It also prints the import time, the largest relative difference between (1) and the two Python
versions (they are independent code of the same equations, so this checks the closed form too),
and the wheel's size when given its path.

    python python/benches/sweep_vs_python.py [--cli target/release/microslip] [--wheel W.whl] [--n 1000000]

Needs numpy and scipy. Units: mm, N, MPa, K_T in MPa/mm.
"""

from __future__ import annotations

import argparse
import math
import os
import subprocess
import sys
import time

import numpy as np
from scipy.optimize import brentq

# The paper's data set (presets/paper-beams.toml), written out so that (2) and (3) read nothing
# from the package they are compared with.
L, B, H, E, P, MU, KT = 200.0, 20.0, 10.0, 210000.0, 1.0, 0.3, 600.0


def constants():
    """F_thre (B3), k (B5), F_1 (B7) and the Coulomb-stick compliance."""
    f_thre = 4.0 * MU * B * H * P / 3.0
    k = 2.0 * math.sqrt(KT / (E * H))
    f_1 = f_thre / (1.0 - 1.0 / math.cosh(k * L))
    return f_thre, k, f_1


def _moment_micro(k, x, tau_b, c, m=np):
    """int_0^X tau(xi) (L xi - xi^2/2) dxi for tau = tau_b - tau_b cosh(k xi) + C sinh(k xi) (B9,
    natural form), by parts: the integrand's polynomial p = L xi - xi^2/2, p' = L - xi, p'' = -1."""
    p, dp, ddp = L * x - x * x / 2.0, L - x, -1.0
    ch, sh = m.cosh(k * x), m.sinh(k * x)
    int_cosh = p * sh / k - dp * ch / k**2 + ddp * sh / k**3 - (-L / k**2)  # minus its value at 0
    int_sinh = p * ch / k - dp * sh / k**2 + ddp * ch / k**3 - (ddp / k**3)
    int_one = L * x * x / 2.0 - x**3 / 6.0
    return tau_b * int_one - tau_b * int_cosh + c * int_sinh


def _tip(force, x, tau_b, tau_x, k, m=np):
    """(B11) at x = L (`m`: numpy for arrays, math for one float): w(L) = F L^3 / (2 E b h^3) - 3 / (2 E h^2) int_0^L tau (L xi - xi^2/2)."""
    c = tau_x / m.sinh(k * x) + tau_b * m.tanh(k * x / 2.0)
    micro = _moment_micro(k, x, tau_b, c, m)
    # The sliding zone [X, L] at tau = mu P.
    macro = MU * P * ((L * L * L / 2.0 - L**3 / 6.0) - (L * x * x / 2.0 - x**3 / 6.0))
    return force * L**3 / (2.0 * E * B * H**3) - 3.0 / (2.0 * E * H * H) * (micro + macro)


def numpy_closed_form(forces: np.ndarray) -> np.ndarray:
    f_thre, k, f_1 = constants()
    lam = k * L
    tau_b = 3.0 * forces / (4.0 * B * H)
    slides = forces > f_1
    # (B8): g(z) = q / sinh z - tanh(z/2) - (lambda - z) = 0 on (0, lambda), one root; bisection.
    q = np.where(slides, f_thre / np.maximum(forces - f_thre, 1e-300), 1.0)
    lo, hi = np.full_like(forces, 1e-12), np.full_like(forces, lam)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        g = q / np.sinh(mid) - np.tanh(mid / 2.0) - (lam - mid)
        lo, hi = np.where(g > 0, mid, lo), np.where(g > 0, hi, mid)
    x = np.where(slides, 0.5 * (lo + hi) / k, L)
    tau_x = np.where(slides, MU * P, tau_b * (1.0 - 1.0 / np.cosh(lam)))
    return _tip(forces, x, tau_b, tau_x, k)


def python_closed_form(forces) -> list:
    f_thre, k, f_1 = constants()
    lam = k * L
    out = []
    for force in forces:
        tau_b = 3.0 * force / (4.0 * B * H)
        if force > f_1:
            q = f_thre / (force - f_thre)
            z = brentq(lambda z: q / math.sinh(z) - math.tanh(z / 2.0) - (lam - z), 1e-12, lam, xtol=1e-14)
            x, tau_x = z / k, MU * P
        else:
            x, tau_x = L, tau_b * (1.0 - 1.0 / math.cosh(lam))
        out.append(_tip(force, x, tau_b, tau_x, k, math))
    return out


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--n", type=int, default=1_000_000)
    parser.add_argument("--cli", default=None, help="the microslip binary (release)")
    parser.add_argument("--wheel", default=None)
    args = parser.parse_args()
    n = args.n

    start = time.perf_counter()
    import microslip  # noqa: E402  (timed: first import in this process)

    print(f"import microslip: {1e3 * (time.perf_counter() - start):.1f} ms")
    beams = microslip.preset("paper-beams")
    forces = np.linspace(0.0, 240.0, n)
    print(f"{n} forces 0..240 N, paper-beams (F_thre = 80 N, F_1 = {constants()[2]:.4f} N); {os.cpu_count()} cores")

    start = time.perf_counter()
    ours = beams.sweep(F=forces)["w_regularized"]
    print(f"1. TwinBeams.sweep:            {time.perf_counter() - start:8.3f} s")

    start = time.perf_counter()
    vectorized = numpy_closed_form(forces)
    print(f"2. NumPy closed form:          {time.perf_counter() - start:8.3f} s")

    start = time.perf_counter()
    looped = np.array(python_closed_form(forces.tolist()))
    print(f"3. pure-Python loop (brentq):  {time.perf_counter() - start:8.3f} s")

    if args.cli:
        cmd = [args.cli, "sweep", "--preset", "paper-beams", "--from", "0", "--to", "240",
               "--points", str(n), "--format", "csv"]
        start = time.perf_counter()
        done = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, check=True)
        took = time.perf_counter() - start
        print(f"4. CLI sweep (CSV to a pipe):  {took:8.3f} s ({len(done.stdout) / 1e6:.0f} MB)")

    def worst(other):
        loaded = forces > 0
        return float(np.max(np.abs(other[loaded] / ours[loaded] - 1.0)))

    print(f"largest relative difference, sweep vs NumPy: {worst(vectorized):.2e}, vs Python loop: {worst(looped):.2e}")
    if args.wheel:
        print(f"wheel {os.path.basename(args.wheel)}: {os.path.getsize(args.wheel) / 1e6:.2f} MB")
    print(f"python {sys.version.split()[0]}, numpy {np.__version__}")


if __name__ == "__main__":
    main()
