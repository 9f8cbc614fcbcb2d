"""Writes synthetic_grid.txt: a SYNTHETIC hazard grid in the layout of NTC 2018
Allegato B (ID, LON, LAT, then ag [g/10], F0, Tc* [s] at TR = 30, 50, 72, 101,
140, 201, 475, 975, 2475 years). The values are made up: a smooth field over a
small lattice, with ag growing with the return period as (TR/475)^0.42, F0 and
Tc* slowly. Not the official grid; see README.md. Run: python3 make_synthetic_grid.py
"""

import math

RETURN_PERIODS = [30, 50, 72, 101, 140, 201, 475, 975, 2475]
LONS = [14.30 + 0.05 * i for i in range(6)]   # 14.30 .. 14.55
LATS = [40.95 + 0.05 * j for j in range(5)]   # 40.95 .. 41.15

lines = [
    "# SYNTHETIC hazard grid for the tests and examples of rocking: NOT the official NTC 2018 grid.",
    "# Layout of NTC 2018 Allegato B; ag in g/10. Made by make_synthetic_grid.py; see README.md.",
    "ID\tLON\tLAT\t" + "\t".join(f"ag_{tr}\tF0_{tr}\tTc*_{tr}" for tr in RETURN_PERIODS),
]
node = 40001
for lat in LATS:
    for lon in LONS:
        x, y = (lon - 14.30) / 0.25, (lat - 40.95) / 0.20
        ag475 = 0.16 + 0.06 * x + 0.03 * y + 0.01 * math.sin(3 * x + 2 * y)  # g
        f0_475 = 2.40 + 0.10 * y
        tc475 = 0.33 + 0.04 * x
        cells = []
        for tr in RETURN_PERIODS:
            r = tr / 475
            ag = ag475 * r ** 0.42
            f0 = f0_475 * r ** 0.02
            tc = tc475 * r ** 0.08
            cells += [f"{10 * ag:.3f}", f"{f0:.3f}", f"{tc:.3f}"]
        lines.append(f"{node}\t{lon:.4f}\t{lat:.4f}\t" + "\t".join(cells))
        node += 1
open("synthetic_grid.txt", "w").write("\n".join(lines) + "\n")
