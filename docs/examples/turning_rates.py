"""The seed's Fig. 12 as a script: the largest reference turning rate of the
geometric construction and the dipole field on 100 generated scenarios.
    python3 turning_rates.py [OUT.png]"""
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

import deepguide

out = sys.argv[1] if len(sys.argv) > 1 else "turning_rates.png"
work = tempfile.mkdtemp()
deepguide.generate_suite(f"{work}/suite", scenarios=100, seed=12)
rows = deepguide.evaluate(f"{work}/suite", ["geometric", "dipole"], f"{work}/out", threads=2).rows
methods = ["geometric", "dipole"]
plt.boxplot([rows["max_rate_ref_deg_s"][rows["method"] == m] for m in methods], labels=methods)
plt.ylabel("largest reference turning rate (deg/s)")
plt.title("100 scenarios, seed 12")
plt.savefig(out, dpi=110)
