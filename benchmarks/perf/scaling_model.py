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

b(P): with many RVEs per rank the rebalance (by measured cost, after every
load step) evens the sums out (b = measured max/mean of the 2x4 run on 2
ranks); with one RVE per rank, an iteration waits for its slowest solve.
Under multiple time stepping (mts N) a solve stops after N DEM steps until
(M9) first holds, so b <= N / (mean DEM steps per solve); that bound is used
for N_IP / P <= 2, the measured b for >= 16, and a linear blend in between.
Rebalancing itself moves an RVE's restart image (~73 kB for lbs_ref) once
per load step, i.e. once in hundreds of iterations: left out.

Usage: scaling_model.py SUMMARY_2x4_2RANKS MACRO_COST_CSV [MTS_CAP] [BARE_US_PER_STEP] [T_SOLVE_3D]
  SUMMARY_2x4_2RANKS: summary.csv of a 2x4 run on 2 ranks (rve_solves,
  rve_rank_max_s, rve_rank_mean_s, dem_steps, macro_iterations)
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

summary = list(csv.DictReader(open(sys.argv[1])))
cost_rows = list(csv.DictReader(open(sys.argv[2])))
cap = float(sys.argv[3]) if len(sys.argv) > 3 else 20.0
bare_us = float(sys.argv[4]) if len(sys.argv) > 4 else 18.1

ranks = 2
solves = sum(int(r["rve_solves"]) for r in summary)
steps = sum(int(r["dem_steps"]) for r in summary)
iterations = sum(int(r["macro_iterations"]) for r in summary)
rve_seconds = ranks * sum(float(r["rve_rank_mean_s"]) for r in summary)
imbalance = sum(float(r["rve_rank_max_s"]) for r in summary) / sum(float(r["rve_rank_mean_s"]) for r in summary)
t_solve = rve_seconds / solves
steps_per_solve = steps / solves
b_single = max(1.0, cap / steps_per_solve)
share = steps * bare_us * 1e-6 / rve_seconds
loop = ranks * sum(float(r.get("rve_loop_mean_s") or "nan") for r in summary)


def per_cell(dim, quadrature):
    rows = [r for r in cost_rows if r["dim"] == str(dim) and r["quadrature"] == quadrature]
    big = max(rows, key=lambda r: int(r["cells"]))  # the largest mesh: set-up effects smallest
    return float(big["s_per_iteration"]) / int(big["cells"]), int(big["cells"])


c2, n2 = per_cell(2, "full")        # [LBS]: 2x2 Gauss points
c3, n3 = per_cell(3, "one point")   # [LSYF]: one point per hexahedron, hourglass control
alpha, beta = 2e-6, 10e9  # assumed: InfiniBand-class latency [s] and bandwidth [B/s]
doubles = {2: 33, 3: 58}  # RveResponse<dim>::packed_size() + the pool's 2 (rve_pool.cpp)

print(f"input t_solve {t_solve * 1e6:.1f} us per RVE solve (2x4 run: {solves} solves, {rve_seconds:.1f} RVE s)")
print(f"input dem_steps_per_solve {steps_per_solve:.2f} steps")
print(f"input loop_share_of_rve_time {loop / rve_seconds:.3f} 1 (rve_loop_mean_s / rve_rank_mean_s: inside LIGGGHTS' time-step loop)")
print(f"input bare_equivalent_share {share:.3f} 1 (DEM steps x {bare_us} us of bare LIGGGHTS on the unloaded packing / RVE seconds)")
print(f"input imbalance_many_rves_per_rank {imbalance:.3f} 1 (2x4 run, 16 RVEs per rank)")
print(f"input imbalance_one_rve_per_rank_bound {b_single:.3f} 1 (cap {cap:g} / {steps_per_solve:.2f} steps)")
print(f"input macro_s_per_iteration_per_cell_2d {c2:.3e} s (neo-Hookean, 2x2 Gauss, measured on {n2} cells)")
print(f"input macro_s_per_iteration_per_cell_3d {c3:.3e} s (neo-Hookean, one point, measured on {n3} cells)")
print(f"input iterations {iterations} (2x4 run); network alpha {alpha:g} s, beta {beta:g} B/s (assumed)")


def efficiency(dim, cells, ips, P, t_rve):
    def T(p):
        per_rank = math.ceil(ips / p)
        w = min(1.0, max(0.0, (per_rank - 2) / 14.0))  # 0 at <= 2 RVEs per rank, 1 at >= 16
        b = (1 - w) * b_single + w * imbalance if p > 1 else 1.0
        gather = (alpha * math.log2(p) + ips * 8 * doubles[dim] / beta) if p > 1 else 0.0
        return (c2 if dim == 2 else c3) * cells + per_rank * t_rve * b + gather

    return T(1) / (P * T(P)), T(P)


cases = [("[LBS] 8x16, 2x2 Gauss (2D)", 2, 128, 512, t_solve),
         ("[LBS] 16x32, 2x2 Gauss (2D)", 2, 512, 2048, t_solve),
         ("3D 16x16x16, one point", 3, 4096, 4096, None),
         ("3D 32x32x32, one point", 3, 32768, 32768, None)]
t_solve_3d = float(sys.argv[5]) if len(sys.argv) > 5 else 9.2e-3  # cost_3d.sh: lsyf-like small_3d solve
print()
print("| mesh | IPs | P | RVEs per rank | seconds per iteration | efficiency |")
print("|---|---|---|---|---|---|")
for name, dim, cells, ips, t in cases:
    t = t if t is not None else t_solve_3d
    for P in (64, 128, 256, 512, 1024):
        if P > ips:
            continue
        e, tp = efficiency(dim, cells, ips, P, t)
        print(f"| {name} | {ips} | {P} | {math.ceil(ips / P)} | {tp:.3g} | {e:.2f} |")
