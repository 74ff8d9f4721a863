#!/usr/bin/python3
"""Scaling model of fe2dem (issue 19): predicted parallel efficiency of one
dynamic-relaxation iteration on P ranks, from pieces measured here.

Per iteration, every rank
  - repeats the macro part (the whole mesh is assembled on every rank):
    t_macro(N_cells) = c_macro * N_cells          [measured: macro_cost.sh]
  - solves its RVEs: ceil(N_IP / P) solves of t_solve seconds, times a
    load-imbalance factor b                      [measured: a 2x4 run]
  - all-gathers every IP's response (s doubles per IP):
    t_gather = alpha * log2(P) + N_IP * 8 s / beta   [network: assumed]
T(P) = t_macro + ceil(N_IP / P) * t_solve * b(P) + t_gather(P);
efficiency E(P) = T(1) / (P T(P)).

b(k), k = RVEs per rank: an iteration waits for its slowest rank. With
sums of k solves per rank the relative spread falls as 1/sqrt(k):
b(k) = 1 + (b1 - 1) / sqrt(k). Two values of b1 bound the estimate:
  - optimistic: b1 = 1 + 4 (m - 1) from m, the measured max/mean of the
    ranks' RVE seconds of the 2x4 run (k = 16);
  - pessimistic: b1 = max/mean over IPs of the DEM steps of each step's
    last solve (history.h5), pooled over steps: the last, unbounded solves
    of a step are the most uneven ones, and the bound applies that spread
    to every solve.
  - calibrated (with --iteration-imbalance): the busiest rank's RVE
    seconds of each iteration over the mean rank's (summary column
    rve_iteration_max_s / rve_rank_mean_s), measured on 2 ranks at k RVEs
    per rank, b_2(k). If the ranks' per-iteration sums were independent and
    normal, the expected maximum of P of them lies m(P) standard deviations
    above the mean (m(2) = 0.564, m(64) = 2.41, m(1024) = 3.20), so
    b(k, P) = 1 + (b_2(k) - 1) m(P) / m(2), b_2 taken at the measured k
    nearest in log k. An estimate, not a bound: correlated delays (one slow
    node) would make it worse.
Rebalancing itself moves an RVE's restart image (~73 kB for lbs_ref) once
per load step, i.e. once in hundreds of iterations: left out.

Usage: scaling_model.py SUMMARY_2x4_2RANKS HISTORY_H5 MACRO_COST_CSV [BARE_US_PER_STEP] [T_SOLVE_3D]
                        [--iteration-imbalance K=SUMMARY ...]
  SUMMARY_2x4_2RANKS: summary.csv of a 2x4 run on 2 ranks (rve_solves,
  rve_rank_max_s, rve_rank_mean_s, dem_steps, macro_iterations);
  HISTORY_H5: that run's history.h5 (per-IP DEM steps of each step's last solve)
  MACRO_COST_CSV: results_macro_cost.csv (seconds per iteration by cells, 2D and 3D)
  BARE_US_PER_STEP: bare LIGGGHTS microseconds per DEM step of lbs_ref
  (overhead.sh), for a second view of the share of RVE time in DEM steps
  T_SOLVE_3D: seconds of one 3D RVE solve (default 9.2e-3: small_3d, 465
  spheres, cost_3d.sh); lsyf_1000/lsyf_4096 solves cost more, which raises
  the efficiency
  --iteration-imbalance K=SUMMARY: summary.csv of a run on 2 ranks with K
  RVEs per rank that has the column rve_iteration_max_s (repeatable; e.g.
  the 1x1, 1x2 and 2x4 meshes: K = 2, 4, 16)
Prints the inputs and a markdown table.
"""
import argparse
import csv
import functools
import math

import h5py

parser = argparse.ArgumentParser(description="Scaling model of fe2dem (see the module docstring).")
parser.add_argument("summary")
parser.add_argument("history")
parser.add_argument("macro_cost")
parser.add_argument("bare_us", nargs="?", type=float, default=18.1)
parser.add_argument("t_solve_3d", nargs="?", type=float, default=9.2e-3)  # cost_3d.sh: small_3d solve
parser.add_argument("--iteration-imbalance", action="append", default=[], metavar="K=SUMMARY")
args = parser.parse_args()
summary = list(csv.DictReader(open(args.summary)))
last_solve_steps = h5py.File(args.history, "r")["dem_steps"][()]  # load steps x IPs
cost_rows = list(csv.DictReader(open(args.macro_cost)))
bare_us, t_solve_3d = args.bare_us, args.t_solve_3d


def column_ratio(rows, numerator, denominator):
    """Sum of one summary.csv column over the load steps, over another's."""
    return sum(float(r[numerator]) for r in rows) / sum(float(r[denominator]) for r in rows)


def iteration_imbalance(path):
    rows = list(csv.DictReader(open(path)))
    if "rve_iteration_max_s" not in rows[0]:
        parser.error(f"{path} has no column rve_iteration_max_s (a summary.csv of fe2dem before issue 19's "
                     "second part); rerun the case")
    return column_ratio(rows, "rve_iteration_max_s", "rve_rank_mean_s")


measured_b2 = {}
for item in args.iteration_imbalance:
    k, _, path = item.partition("=")
    if not k.isdigit() or not path:
        parser.error(f"--iteration-imbalance '{item}': expected K=SUMMARY, e.g. 16=summary.csv")
    measured_b2[int(k)] = iteration_imbalance(path)


@functools.lru_cache(maxsize=None)  # one quadrature per rank count, not one per table cell
def expected_max_of_normals(p):
    """E[max of p independent standard normals], by quadrature."""
    h, total = 1e-3, 0.0
    for i in range(-8000, 8001):
        x = i * h
        phi = math.exp(-0.5 * x * x) / math.sqrt(2.0 * math.pi)
        cdf = 0.5 * (1.0 + math.erf(x / math.sqrt(2.0)))
        total += x * p * phi * cdf ** (p - 1) * h
    return total


def b_calibrated(k, p):
    nearest = min(measured_b2, key=lambda m: abs(math.log(m) - math.log(k)))
    return 1.0 + (measured_b2[nearest] - 1.0) * expected_max_of_normals(p) / expected_max_of_normals(2)

ranks = 2
solves = sum(int(r["rve_solves"]) for r in summary)
steps = sum(int(r["dem_steps"]) for r in summary)
iterations = sum(int(r["macro_iterations"]) for r in summary)
rve_seconds = ranks * sum(float(r["rve_rank_mean_s"]) for r in summary)
loop = ranks * sum(float(r.get("rve_loop_mean_s") or "nan") for r in summary)
imbalance = column_ratio(summary, "rve_rank_max_s", "rve_rank_mean_s")
t_solve = rve_seconds / solves
b1_optimistic = 1.0 + 4.0 * (imbalance - 1.0)
b1_pessimistic = last_solve_steps.max(axis=1).sum() / last_solve_steps.mean(axis=1).sum()


def per_cell(dim, quadrature):
    rows = [r for r in cost_rows if r["dim"] == str(dim) and r["quadrature"] == quadrature]
    big = max(rows, key=lambda r: int(r["cells"]))  # the largest mesh: set-up effects smallest
    return float(big["s_per_iteration"]) / int(big["cells"]), int(big["cells"])


c2, n2 = per_cell(2, "full")  # [LBS]: 2x2 Gauss points
c3, n3 = per_cell(3, "one point")  # [LSYF]: one point per hexahedron, hourglass control
alpha, beta = 2e-6, 10e9  # assumed: InfiniBand-class latency [s] and bandwidth [B/s]
doubles = {2: 33, 3: 58}  # RveResponse<dim>::packed_size() + the pool's 2 (rve_pool.cpp)

print(f"input t_solve {t_solve * 1e6:.1f} us per RVE solve (2x4 run: {solves} solves, {rve_seconds:.1f} RVE s)")
print(f"input dem_steps_per_solve {steps / solves:.2f} steps")
print(f"input loop_share_of_rve_time {loop / rve_seconds:.3f} 1 (rve_loop_mean_s / rve_rank_mean_s)")
print(f"input bare_equivalent_share {steps * bare_us * 1e-6 / rve_seconds:.3f} 1 "
      f"(DEM steps x {bare_us} us of bare LIGGGHTS on the unloaded packing / RVE seconds)")
print(f"input imbalance_16_rves_per_rank {imbalance:.3f} 1 (2x4 run, max/mean of the ranks' RVE seconds)")
print(f"input b1_optimistic {b1_optimistic:.3f} 1")
print(f"input b1_pessimistic {b1_pessimistic:.3f} 1 (pooled max/mean over IPs of the last solve's DEM steps)")
print(f"input macro_s_per_iteration_per_cell_2d {c2:.3e} s (neo-Hookean, 2x2 Gauss, {n2} cells)")
print(f"input macro_s_per_iteration_per_cell_3d {c3:.3e} s (neo-Hookean, one point, {n3} cells)")
print(f"input t_solve_3d {t_solve_3d:.3e} s; network alpha {alpha:g} s, beta {beta:g} B/s (assumed)")
for k in sorted(measured_b2):
    print(f"input iteration_imbalance_2_ranks_{k}_rves_per_rank {measured_b2[k]:.3f} 1 "
          "(sum of rve_iteration_max_s / sum of rve_rank_mean_s)")


def seconds(dim, cells, ips, p, t_rve, b1=None):
    k = math.ceil(ips / p)
    if p == 1:
        b = 1.0
    elif b1 is None:
        b = b_calibrated(k, p)
    else:
        b = 1.0 + (b1 - 1.0) / math.sqrt(k)
    gather = (alpha * math.log2(p) + ips * 8 * doubles[dim] / beta) if p > 1 else 0.0
    return (c2 if dim == 2 else c3) * cells + k * t_rve * b + gather


cases = [("[LBS] 8x16, 2x2 Gauss (2D)", 2, 128, 512, t_solve),
         ("[LBS] 16x32, 2x2 Gauss (2D)", 2, 512, 2048, t_solve),
         ("3D 16x16x16, one point", 3, 4096, 4096, t_solve_3d),
         ("3D 32x32x32, one point", 3, 32768, 32768, t_solve_3d)]
print()
calibrated = bool(measured_b2)
print("| mesh | IPs | P | RVEs per rank | seconds per iteration | efficiency (pessimistic - optimistic) |"
      + (" efficiency (calibrated) |" if calibrated else ""))
print("|---|---|---|---|---|---|" + ("---|" if calibrated else ""))
for name, dim, cells, ips, t in cases:
    t1 = seconds(dim, cells, ips, 1, t, 1.0)
    for P in (64, 128, 256, 512, 1024):
        if P > ips:
            continue
        worst, best = (seconds(dim, cells, ips, P, t, b1) for b1 in (b1_pessimistic, b1_optimistic))
        row = (f"| {name} | {ips} | {P} | {math.ceil(ips / P)} | {best:.3g} - {worst:.3g} | "
               f"{t1 / (P * worst):.2f} - {t1 / (P * best):.2f} |")
        if calibrated:
            row += f" {t1 / (P * seconds(dim, cells, ips, P, t)):.2f} |"
        print(row)
