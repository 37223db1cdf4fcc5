#!/usr/bin/env python3
"""CalculiX deck for the clamped double-lap joint (microslip docs/theory.md section 9), half model.

Half model about the inner plate's mid-plane: inner plate y in [0, t1/2] (u_y = 0 at y = 0),
one cover y in [t1/2, t1/2 + t2]. x = 0: inner plate's free end inside the overlap, x = L: the
cover's free end. Cover runs over [-Lc, L] (end face x = -Lc fixed, u_x = u_y = 0), inner plate
over [0, L + Li] (uniform traction F/(b t1) on its end face). Pressure P on the cover's outer face
over [0, L] only.

Plane stress: C3D20R, one element across a slice of width W (symmetry u_z = 0 on z = 0, free face
z = W). Every load is a traction (pressure P, end traction F/(b t1)), so the slice width does not
enter; the plane-stress field per unit width is the joint's (b = 25 mm) field.

Usage: gen.py NAME key=value ...   (writes NAME.inp and NAME.json with the node sets' layout)
"""
import json
import sys

P = dict(L=40.0, b=25.0, t1=3.0, t2=2.0, E=70000.0, E2=0.0, nu=0.3, Pr=10.0, mu=0.3, KT=1000.0,
         Lc=10.0, Li=10.0, W=0.5,
         n1=4, n2=4,          # elements through the inner half thickness / the cover
         he=0.25, hm=1.0,     # element length at the overlap ends / largest in the overlap
         hx=1.0,              # largest element length in the extensions
         growth=1.15,
         dF=100.0,            # force step (N, on the whole joint)
         forces="1000,2000,2400,3000,4500,5500",
         incs="",             # increments per force step, comma list (overrides dF when given)
         tol=0.0,             # *CONTROLS residual and correction tolerance (0: CalculiX defaults)
         KN=0.0,              # normal penalty (0: max(100 E / smallest element height, 10 KT))
         )


def graded(length, h0, hmax, g):
    """Points 0..length, first element h0, growing by g up to hmax, scaled to end exactly."""
    sizes = []
    s = 0.0
    h = h0
    while s < length - 1e-12:
        sizes.append(h)
        s += h
        h = min(h * g, hmax)
    # scale so that the sizes add up to length (the last one may overshoot)
    if s - length > 0.5 * sizes[-1] and len(sizes) > 1:
        sizes.pop()
    tot = sum(sizes)
    sizes = [x * length / tot for x in sizes]
    pts = [0.0]
    for x in sizes:
        pts.append(pts[-1] + x)
    pts[-1] = length
    return pts


def main():
    name = sys.argv[1]
    for kv in sys.argv[2:]:
        k, v = kv.split("=")
        P[k] = type(P[k])(v) if not isinstance(P[k], str) else v
    L, t1, t2, Lc, Li, W = P["L"], P["t1"], P["t2"], P["Lc"], P["Li"], P["W"]
    h1 = t1 / 2
    half = graded(L / 2, P["he"], P["hm"], P["growth"])
    ov = half + [L - x for x in reversed(half[:-1])]
    ext_c = [-x for x in reversed(graded(Lc, P["he"], P["hx"], P["growth"]))]
    ext_i = [L + x for x in graded(Li, P["he"], P["hx"], P["growth"])]
    xs_cover = ext_c[:-1] + ov
    xs_inner = ov + ext_i[1:]
    ys_inner = [h1 * j / P["n1"] for j in range(P["n1"] + 1)]
    ys_cover = [h1 + t2 * j / P["n2"] for j in range(P["n2"] + 1)]
    zs = [0.0, W]

    nodes = {}   # id -> (x, y, z)
    out = []
    next_node = [1]
    next_el = [1]

    def block(xs, ys, zs):
        """Half-grid of a structured C3D20R block; returns (node id grid dict, element list)."""
        def half(v):
            h = []
            for i in range(len(v) - 1):
                h += [v[i], 0.5 * (v[i] + v[i + 1])]
            return h + [v[-1]]
        hx, hy, hz = half(xs), half(ys), half(zs)
        grid = {}
        for k in range(len(hz)):
            for j in range(len(hy)):
                for i in range(len(hx)):
                    if (i % 2) + (j % 2) + (k % 2) >= 2:
                        continue
                    grid[(i, j, k)] = next_node[0]
                    nodes[next_node[0]] = (hx[i], hy[j], hz[k])
                    next_node[0] += 1
        els = []
        for ez in range(len(zs) - 1):
            for ey in range(len(ys) - 1):
                for ex in range(len(xs) - 1):
                    i, j, k = 2 * ex, 2 * ey, 2 * ez
                    c = [(i, j, k), (i + 2, j, k), (i + 2, j + 2, k), (i, j + 2, k),
                         (i, j, k + 2), (i + 2, j, k + 2), (i + 2, j + 2, k + 2), (i, j + 2, k + 2)]
                    m = [(i + 1, j, k), (i + 2, j + 1, k), (i + 1, j + 2, k), (i, j + 1, k),
                         (i + 1, j, k + 2), (i + 2, j + 1, k + 2), (i + 1, j + 2, k + 2), (i, j + 1, k + 2),
                         (i, j, k + 1), (i + 2, j, k + 1), (i + 2, j + 2, k + 1), (i, j + 2, k + 1)]
                    els.append((next_el[0], [grid[q] for q in c + m], (ex, ey, ez)))
                    next_el[0] += 1
        return grid, els, (len(xs) - 1, len(ys) - 1)

    gi, ei, (nxi, nyi) = block(xs_inner, ys_inner, zs)
    gc, ec, (nxc, nyc) = block(xs_cover, ys_cover, zs)
    n_ov = len(ov) - 1
    off_c = len(ext_c) - 1  # cover element columns before x = 0

    # ground node for the weak spring on the inner plate (x direction)
    ground = next_node[0]
    nodes[ground] = (L + Li + 10.0, 0.0, 0.0)
    spring_node = gi[(2 * nxi, 0, 0)]

    KT = P["KT"]
    hmin = min(h1 / P["n1"], t2 / P["n2"])
    E2 = P["E2"] if P["E2"] > 0 else P["E"]
    KN = P["KN"] if P["KN"] > 0 else max(100 * max(P["E"], E2) / hmin, 10 * KT)
    sigma = lambda F: F / (P["b"] * t1)

    o = out.append
    o("** microslip double-lap joint, half model, C3D20R plane-stress slice; " +
      " ".join(f"{k}={v}" for k, v in P.items()))
    o("*HEADING\nlap joint KT=%g" % KT)
    o("*NODE, NSET=NALL")
    for nid, (x, y, z) in nodes.items():
        o(f"{nid}, {x:.12g}, {y:.12g}, {z:.12g}")
    for setname, els in (("EINNER", ei), ("ECOVER", ec)):
        o(f"*ELEMENT, TYPE=C3D20R, ELSET={setname}")
        for eid, nn, _ in els:
            o(f"{eid}, " + ", ".join(map(str, nn[:15])) + ",")
            o(", ".join(map(str, nn[15:])))
    sp = next_el[0]
    o("*ELEMENT, TYPE=SPRINGA, ELSET=ESPRING")
    o(f"{sp}, {spring_node}, {ground}")
    o("*SPRING, ELSET=ESPRING\n\n1.e-4")

    def nset(name, ids):
        o(f"*NSET, NSET={name}")
        ids = list(ids)
        for q in range(0, len(ids), 10):
            o(", ".join(map(str, ids[q:q + 10])))

    nset("SYMY", [n for (i, j, k), n in gi.items() if j == 0])
    nset("SYMZ", [n for n, (x, y, z) in nodes.items() if z == 0.0 and n != ground])
    nset("CLAMP", [n for (i, j, k), n in gc.items() if i == 0])
    nset("GROUND", [ground])
    # printed sets, z = 0 face only
    i_L = 2 * n_ov            # half-grid index of x = L in the inner block
    i_0c = 2 * off_c          # half-grid index of x = 0 in the cover block
    inner_L = [gi[(i_L, j, 0)] for j in range(2 * nyi + 1)]
    cover_0 = [gc[(i_0c, j, 0)] for j in range(2 * nyc + 1)]
    inner_face = [gi[(i, 2 * nyi, 0)] for i in range(0, 2 * n_ov + 1)]
    cover_face = [gc[(i_0c + i, 0, 0)] for i in range(0, 2 * n_ov + 1)]
    nset("IL", inner_L)
    nset("C0", cover_0)
    nset("IFACE", inner_face)
    nset("CFACE", cover_face)
    # surfaces: inner top (S5) over the overlap, cover bottom (S3) over the overlap
    o("*SURFACE, NAME=SINNERTOP, TYPE=ELEMENT")
    for eid, _, (ex, ey, ez) in ei:
        if ey == nyi - 1 and ex < n_ov:
            o(f"{eid}, S5")
    o("*SURFACE, NAME=SCOVERBOT, TYPE=ELEMENT")
    for eid, _, (ex, ey, ez) in ec:
        if ey == 0 and ex >= off_c:
            o(f"{eid}, S3")
    o(f"*MATERIAL, NAME=AL\n*ELASTIC\n{P['E']}, {P['nu']}")
    o(f"*MATERIAL, NAME=COV\n*ELASTIC\n{E2}, {P['nu']}")
    o("*SOLID SECTION, ELSET=EINNER, MATERIAL=AL\n*SOLID SECTION, ELSET=ECOVER, MATERIAL=COV")
    o("*SURFACE INTERACTION, NAME=JENKINS\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR")
    o(f"{KN:.6e}\n*FRICTION\n{P['mu']}, {KT:.6e}")
    o("*CONTACT PAIR, INTERACTION=JENKINS, TYPE=SURFACE TO SURFACE\nSCOVERBOT, SINNERTOP")
    o("*BOUNDARY\nSYMY, 2, 2\nSYMZ, 3, 3\nCLAMP, 1, 2\nGROUND, 1, 3")

    def prints():
        fr = ", FREQUENCY=100000"
        for s in ("IL", "C0", "IFACE", "CFACE"):
            o(f"*NODE PRINT, NSET={s}{fr}\nU")
        o(f"*NODE FILE, NSET=IFACE{fr}\nU")
        o(f"*CONTACT FILE{fr}\nCDIS, CSTR")

    def controls():
        if P["tol"] > 0:
            # R_alpha^n, C_alpha^n (defaults 0.005, 0.01): residual / correction tolerances
            o(f"*CONTROLS, PARAMETERS=FIELD\n{P['tol']:.3e}, {P['tol']:.3e}")
            o("*CONTROLS, PARAMETERS=TIME INCREMENTATION\n40, 60, 9, 200, 10, 4, 12, 5")

    o("** step 1: clamping pressure on the cover's outer face over [0, L]")
    o("*STEP, INC=1000\n*STATIC\n1., 1.")
    controls()
    o("*DLOAD")
    for eid, _, (ex, ey, ez) in ec:
        if ey == nyc - 1 and ex >= off_c:
            o(f"{eid}, P5, {P['Pr']}")
    prints()
    o("*END STEP")
    forces = [float(f) for f in P["forces"].split(",")]
    prev = 0.0
    incs = [int(q) for q in P["incs"].split(",")] if P["incs"] else None
    for n, F in enumerate(forces):
        inc = P["dF"] / (F - prev) if incs is None else 1.0 / incs[n]
        inc = min(inc, 1.0)
        o(f"** step {n + 2}: F = {F} N (traction {sigma(F):.6g} MPa on the inner end face), "
          f"increments of {P['dF']} N")
        o(f"*STEP, INC=100000\n*STATIC\n{inc:.9e}, 1., {inc * 1e-3:.9e}, {inc:.9e}")
        controls()
        o("*DLOAD")
        for eid, _, (ex, ey, ez) in ei:
            if ex == nxi - 1:
                o(f"{eid}, P4, {-sigma(F):.12g}")
        prints()
        o("*END STEP")
        prev = F
    with open(name + ".inp", "w") as f:
        f.write("\n".join(out) + "\n")
    meta = dict(params=P, forces=forces, KN=KN,
                IL=[(n, nodes[n][1]) for n in inner_L], C0=[(n, nodes[n][1]) for n in cover_0],
                IFACE=[(n, nodes[n][0]) for n in inner_face], CFACE=[(n, nodes[n][0]) for n in cover_face],
                n_elements=len(ei) + len(ec), n_nodes=len(nodes))
    with open(name + ".json", "w") as f:
        json.dump(meta, f)
    print(f"{name}: {len(ei) + len(ec)} elements, {len(nodes)} nodes, KN={KN:.3g}")


if __name__ == "__main__":
    main()
