"""Print the markdown table of the overlap compact-formula constants (doc/compact.md)
from data/fit_coefficients.csv, so that the document never holds hand-typed numbers.
Usage: python3 gen/compact_table.py [data/fit_coefficients.csv]"""
import sys

path = sys.argv[1] if len(sys.argv) > 1 else "data/fit_coefficients.csv"
par = {}
for line in open(path):
    f = line.strip().split(",")
    if len(f) == 3 and f[0] == "param":
        par[f[1]] = float(f[2])
pairs = [("a", "cov_inv_a"), ("b", "cov_inv_t"), ("p", "cov_fwd_l"), ("q", "cov_fwd_t")]
print("| constant | value | constant | value |")
print("|---|---|---|---|")
for left, right in [(pairs[0], pairs[1]), (pairs[2], pairs[3])]:
    for i in range(1, 5):
        print(f"| {left[0]}{i} | {par[f'{left[1]}_{i}']:.17E} | {right[0]}{i} | {par[f'{right[1]}_{i}']:.17E} |")
