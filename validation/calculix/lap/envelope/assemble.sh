#!/bin/bash
# Builds ENVELOPE.md from the hand-written parts and the generated tables.
cd "$(dirname "$0")"
python3 analyse.py > table_cases_raw.md
python3 report.py > tables_grid_cases.md
python3 envelope.py > envelope_out.txt
python3 conv.py C14 C07 C12 C09 C10 > conv_out.md
{
cat ENVELOPE_head.md
cat ENVELOPE_body1.md
echo
echo "## 3. The grid"
echo
echo "Fixed: b = 25 mm, E1 = 70000 MPa, nu = 0.3 (CalculiX). lambda^2 = 2 K_T (1/(E1 t1) + 1/(2 E2 t2)); eps = K_T/K_eff - 1; m, b as in section 7 (b is called beta here). Lengths in mm."
echo
awk 'BEGIN{p=1} /^$/{exit} {print}' tables_grid_cases.md
echo
echo "## 4. Per-state results (coarse meshes)"
echo
echo "err = Delta_ccx/Delta_cf - 1; err at K_eff against the closed form at K_eff; r_keff = Delta_cf(K_eff)/Delta_cf - 1. a, d: CalculiX a_s, d_s (K_T slip >= mu P) / closed form / closed form at K_eff. p(0), p(L): CalculiX's nodal CPRESS at the overlap ends. C02's third level (0.988 F_gross) did not converge and is absent."
echo
awk 'f{print} /^$/{f=1}' tables_grid_cases.md
echo
echo "## 5. Convergence spot checks"
echo
echo "Variants: f = every element size halved (he, hm, hx, and 8 + 8 elements through the thicknesses), i = every force increment halved (one-increment levels stay one increment), x2 = the plates' extensions Lc, Li doubled (the supports moved away from the overlap). C14: stiffest K_T (1e5) and shortest (L/t1 = 3); C07: thickest (t1 = t2 = 6); C12: short, dissimilar; C09: the largest calibration error (prestress); C10: the joint that sets the bound's constant."
echo
cat conv_out.md
cat ENVELOPE_body2.md
echo
echo "### Per-state bound table (all cases)"
echo
echo "B = r + 2.0 q_p + 0.36 b + 0.013; B_k = 1.9 q_p + 0.32 b + 0.013; B_w = 1.25 B. Verdict from B_w. \"EXCEEDED\": |err| > B or |err_keff| > B_k (fitted, unwidened) in the domain."
echo
sed -n '/^| case/,/^$/p' envelope_out.txt
tail -2 envelope_out.txt
cat ENVELOPE_body3.md
} > ENVELOPE.md
wc -l ENVELOPE.md
