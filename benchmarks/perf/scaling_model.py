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
Rebalancing itself moves an RVE's restart image (~73 kB for lbs_ref) once
per load step, i.e. once in hundreds of iterations: left out.

Usage: scaling_model.py SUMMARY_2x4_2RANKS HISTORY_H5 MACRO_COST_CSV [BARE_US_PER_STEP] [T_SOLVE_3D]
  SUMMARY_2x4_2RANKS: summary.csv of a 2x4 run on 2 ranks (rve_solves,
  rve_rank_max_s, rve_rank_mean_s, dem_steps, macro_iterations);
  HISTORY_H5: that run's history.h5 (per-IP DEM steps of each step's last solve)
  MACRO_COST_CSV: results_macro_cost.csv (seconds per iteration by cells, 2D and 3D)
  BARE_US_PER_STEP: bare LIGGGHTS microseconds per DEM step of lbs_ref
  (overhead.sh), for a second view of the share of RVE time in DEM steps
  T_SOLVE_3D: seconds of one 3D RVE solve (default 9.2e-3: small_3d, 465
  spheres, cost_3d.sh); lsyf_1000/lsyf_4096 solves cost more, which raises
  the efficiency
Prints the inputs and a markdown table.
"""
import csv
import math
import sys

import h5py

summary = list(csv.DictReader(open(sys.argv[1])))
last_solve_steps = h5py.File(sys.argv[2], "r")["dem_steps"][()]  # load steps x IPs
cost_rows = list(csv.DictReader(open(sys.argv[3])))
bare_us = float(sys.argv[4]) if len(sys.argv) > 4 else 18.1
t_solve_3d = float(sys.argv[5]) if len(sys.argv) > 5 else 9.2e-3  # cost_3d.sh: small_3d solve

ranks = 2
solves = sum(int(r["rve_solves"]) for r in summary)
steps = sum(int(r["dem_steps"]) for r in summary)
iterations = sum(int(r["macro_iterations"]) for r in summary)
rve_seconds = ranks * sum(float(r["rve_rank_mean_s"]) for r in summary)
loop = ranks * sum(float(r.get("rve_loop_mean_s") or "nan") for r in summary)
imbalance = sum(float(r["rve_rank_max_s"]) for r in summary) / sum(float(r["rve_rank_mean_s"]) for r in summary)
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


def seconds(dim, cells, ips, p, t_rve, b1):
    k = math.ceil(ips / p)
    b = 1.0 + (b1 - 1.0) / math.sqrt(k) if p > 1 else 1.0
    gather = (alpha * math.log2(p) + ips * 8 * doubles[dim] / beta) if p > 1 else 0.0
    return (c2 if dim == 2 else c3) * cells + k * t_rve * b + gather


cases = [("[LBS] 8x16, 2x2 Gauss (2D)", 2, 128, 512, t_solve),
         ("[LBS] 16x32, 2x2 Gauss (2D)", 2, 512, 2048, t_solve),
         ("3D 16x16x16, one point", 3, 4096, 4096, t_solve_3d),
         ("3D 32x32x32, one point", 3, 32768, 32768, t_solve_3d)]
print()
print("| mesh | IPs | P | RVEs per rank | seconds per iteration | efficiency (pessimistic - optimistic) |")
print("|---|---|---|---|---|---|")
for name, dim, cells, ips, t in cases:
    t1 = seconds(dim, cells, ips, 1, t, 1.0)
    for P in (64, 128, 256, 512, 1024):
        if P > ips:
            continue
        worst, best = (seconds(dim, cells, ips, P, t, b1) for b1 in (b1_pessimistic, b1_optimistic))
        print(f"| {name} | {ips} | {P} | {math.ceil(ips / P)} | {best:.3g} - {worst:.3g} | "
              f"{t1 / (P * worst):.2f} - {t1 / (P * best):.2f} |")
