"""Mean MSI against L/B for the NPL 5b-like catamaran family at 1000 t and 40 kn, in a 3 m, Tz 7.5 s head sea.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/msi_vs_L_over_B.py [out.png]

Each point is one hull from the generator (other variables as Table 1's NPL 5b), its RAOs by the time-domain
strip method at 20 sections x 8 panels (quick; the study uses 40 x 14) with Cs 0.065, and the O'Hanlon &
McCauley MSI averaged over the forward, LCG and transom positions.
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import hullopt  # noqa: E402

speed_m_s = 40 * 1852.0 / 3600.0
sea = {"Hs_m": 3.0, "Tz_s": 7.5}
L_over_B = np.linspace(9.0, 15.0, 7)
msi, length = [], []
for lb in L_over_B:
    dv = hullopt.DesignVariables(type="catamaran", L_over_B=float(lb), B_over_T=2.0, Cb=0.40, Cp=0.69, Cwp=0.76,
                                 LCB_pct_L=-6.4, LCF_pct_L=-8.3)
    hull = hullopt.generate_hull(dv)
    mass = hullopt.mass_properties(hull)
    rao = hullopt.compute_raos(hull, mass, speed_m_s, hullopt.evaluation_frequencies(),
                               solver={"sections": 20, "panels": 8, "Cs": 0.065})
    result = hullopt.evaluate(rao, hull, mass, seas=[sea])[0]
    msi.append(result["mean"]["msi_pct"])
    length.append(hullopt.hydrostatics(hull)["L_m"])
    print(f"L/B {lb:5.2f}  L {length[-1]:6.2f} m  mean MSI {msi[-1]:5.1f} %")

fig, ax = plt.subplots(figsize=(6, 4))
ax.plot(L_over_B, msi, "o-")
ax.set_xlabel("L/B [-]")
ax.set_ylabel("mean MSI, 2 h exposure [%]")
ax.set_title("NPL 5b-like catamaran, 1000 t, 40 kn, Hs 3 m, Tz 7.5 s")
ax.grid(True, alpha=0.3)
fig.tight_layout()
out = sys.argv[1] if len(sys.argv) > 1 else "msi_vs_L_over_B.png"
os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
fig.savefig(out, dpi=120)
print(f"wrote {out}")
