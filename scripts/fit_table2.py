#!/usr/bin/env python3
"""Infers the two-layer materials of Donner and Jensen's Table 2, which the
paper describes only in words (Figure 3's caption), by fitting our Monte Carlo
to the paper's Monte Carlo column: the layers' shape is fixed from the words
(g = 0, matched indices, 1 mm mean free paths as in Figure 2, scattering
0.5/mm for "low-scattering" and 10/mm for "highly scattering"), and a shared
absorption plus the lower layer's thickness are bisected until our MC gives
the paper's R and T. Writes nothing: the fitted stacks were saved by hand to
materials/table2-*.json. Needs build/shadertwin. See docs/optics.md.
The "right" material (a substrate of infinite thickness, T = 0) fits only
the substrate's absorption, with a 0.2 mm top of sigma_s 10/mm.
"""
import json, subprocess, sys, math
import os
BIN = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "build", "shadertwin")
def run(layers, model="multipole", extra=()):
    with open("/tmp/fit_table2_layers.json", "w") as f: json.dump(layers, f)
    out = subprocess.run([BIN, "slab", "--layers", "/tmp/fit_table2_layers.json", "--json", "--model", model, *extra], capture_output=True, text=True)
    if out.returncode: print(out.stderr); sys.exit(1)
    j = json.loads(out.stdout); return j["R"][0], j["T"][0] + j["T_direct"][0]
def layer(sa, ss, d, eta=1.0, g=0.0): return {"sigma_a": [sa]*3, "sigma_s": [ss]*3, "g": g, "eta": eta, "thickness": d}
def mc(layers): return run(layers, "mc", ("--photons", "30000"))
def fit(name, top, bottom_ss, R_t, T_t):
    sa, d2 = 0.003, 2.0
    for outer in range(3):
        lo, hi = 0.2, 20.0
        for it in range(7):
            d2 = (lo*hi) ** 0.5
            R, T = mc([layer(sa, top[0], top[1]), layer(sa, bottom_ss, d2)])
            if T > T_t: lo = d2
            else: hi = d2
        lo2, hi2 = 1e-5, 0.1
        for it in range(7):
            sa = (lo2*hi2) ** 0.5
            R, T = mc([layer(sa, top[0], top[1]), layer(sa, bottom_ss, d2)])
            if R > R_t: lo2 = sa
            else: hi2 = sa
        print(name, "iter", outer, "sa", round(sa,5), "d2", round(d2,3), "MC", round(R,4), round(T,4), flush=True)
    L = [layer(sa, top[0], top[1]), layer(sa, bottom_ss, d2)]
    print(name, json.dumps(L))
    print(name, "MC", mc(L), "KM", run(L), "noKM", run(L, extra=("--no-km",)), flush=True)
fit("left", (0.5, 8.0), 10.0, 0.851, 0.0115)
fit("middle", (0.5, 1.0), 10.0, 0.948, 0.035)
