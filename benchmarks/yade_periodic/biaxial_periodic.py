# -*- coding: utf-8 -*-
"""
biaxial_periodic.py -- independent YADE reference for the FE2DEM 2D granular RVE.

Usage (no GUI, one thread):

    yade -n -x -j1 biaxial_periodic.py PACKING.periodic.data OUT.csv RATE_FACTOR

    PACKING      LIGGGHTS write_data file (atom_style sphere:
                 id type diameter density x y z ix iy iz), periodic box.
    OUT.csv      results at the packing as read, at the end of the isotropic
                 stage and at every 0.5 % of axial strain (see COLUMNS below).
                 A denser trace (every 0.1 %) goes to OUT_trace.csv.
    RATE_FACTOR  multiplies the base axial strain rate BASE_RATE (1 = base
                 rate, 0.5 = half rate for the rate-independence check).

What it does
------------
The periodic disc packing is put, unchanged, in a fully periodic YADE cell
(Lx x Ly from the file, Lz = 20 Rmax so that no sphere sees its own z image).
The discs are YADE spheres in the plane z = 0 (cell coordinate: z = 0 lies on
the z period boundary, which is harmless with periodic collision detection),
with z translation and x/y rotations blocked (blockedDOFs 'zXY'), disc mass
m = RHO2D pi r^2 and disc inertia 0.5 m r^2.  The cell is deformed only
through a diagonal Cell.velGrad (no shear, cell stays rectangular, z size
fixed); YADE moves the particles with the mean field (Cell.homoDeform = 2).

  0. packing as read: one step with the integrator switched off counts the
     contacts (overlap > 0) and gives the stress (normal forces only: the
     tangential spring history is not in a write_data file; it does not
     change the pressure, since f_t . l = 0).
  1. isotropic compression: the target stresses (s11, s22) are ramped
     linearly from the initial values to -P in N_RAMP steps and tracked by
     two independent PI servos on velGrad_xx and velGrad_yy; then held
     until |s_ii + P| < ISO_TOL P and YADE's unbalanced force is below
     ISO_UNB for ISO_HOLD consecutive steps (relaxed, quasi-static state).
     Lx_ic, Ly_ic are the cell sizes at that point.
  2. biaxial: velGrad_yy = -RATE (constant true strain rate in y) until the
     axial strain 1 - Ly/Ly_ic reaches EPS_END, while the PI servo on
     velGrad_xx holds s11 = -P.  At every REC_STEP of axial strain the
     state is recorded; if at that moment the lateral stress error exceeds
     REC_TOL, the axial motion is halted (velGrad_yy = 0) until the servo
     has brought it below REC_TOL/2 (counted in the column hold_steps; a
     pause at fixed axial strain, i.e. a short relaxation).

Units and signs
---------------
SI: m, kg, s, N.  Stresses are 2D stresses (force per unit length, N/m):
sigma_2D = YADE 3D stress (utils.getStress, N/m^2) * Lz.  This is the same
as (1/(Lx Ly)) * sum_c f_c (x) l_c, independent of Lz.
Sign: tension positive, compression negative (this is YADE's own sign in
utils.getStress; checked: the packing as read gives s11, s22 < 0).
Strains: axial_strain = 1 - Ly/Ly_ic > 0 in compression;
J_rel = Lx Ly/(Lx_ic Ly_ic) - 1 (< 0 = contraction, > 0 = dilation).

Parameters (and why)
--------------------
KN = 1e7 N/m, KS = 2e6 N/m  same linear contact as the LIGGGHTS RVE.
    Imposed as constants for every contact through the MatchMaker
    attributes kn, ks of Ip2_FrictMat_FrictMat_FrictPhys (algo 'val'),
    which YADE 2023.02 evaluates instead of the young*radius harmonic mean.
    Checked in stage 0: |F_n - KN * overlap| over all contacts is printed.
MU = 0.4   Coulomb friction (FrictMat.frictionAngle = atan(MU));
    Law2_ScGeom_FrictPhys_CundallStrack: F_n = kn * overlap, incremental
    tangential spring ks, |F_t| <= MU F_n; no viscous contact damping.
DAMP = 0.7  Cundall local non-viscous damping (NewtonIntegrator.damping) on
    forces and moments; YADE damps the fluctuating velocity (mean field
    removed) with a mid-step velocity estimate.
RHO2D = 2000 kg/m^2  areal density: m = RHO2D pi r^2 (the density column of
    the file is not used: LIGGGHTS write_data in 2D may store
    rmass/(4/3 pi r^3) there).
DT = 1e-6 s  time step; the script prints the stiffness-based estimate
    min_i sqrt(m_i / sum_c kn) (translation, 1.64e-6 s for lbs_ref) and the
    rotational analogue min_i sqrt(I_i / sum_c ks r_i^2) (2.59e-6 s); the
    critical step of the spring network is >= sqrt(2) x these, so DT is
    <= 0.43 of it.  A run at DT = 5e-7 (override) agreed pre-peak (README).
P = 1.5e5 N/m  confining stress (150 kN/m).
EPS_END = 0.10, REC_STEP = 0.005  axial strain end and record step.
BASE_RATE = 0.1 1/s  base axial (true) strain rate: 10 % in ~1.05 s =
    1.05e6 steps.  Inertial number I = RATE d_mean sqrt(RHO2D/P) ~ 4e-6,
    far below the usual quasi-static limit 1e-3; the half-rate run checks it
    (and a trial at 1 1/s gave the same pre-peak curve to 3 digits).
Servo (PI on the diagonal of velGrad, updated every NCTL = 10 steps):
    e = target - s_ii (N/m, > 0 = too much compression -> expand),
    D = (e + (1/TI) int e dt) / (K_aff TAU), |D| <= DMAX,
    K_aff = (1/A) sum_c KN l_c^2 n_i^4 (affine stiffness, an upper bound of
    the true one, so the loop closes in >= TAU: stable).  TAU = 1e-4 s
    (about a wave crossing of the cell; 2e-4 s gave larger lateral errors
    after the peak), TI = 2e-3 s.
N_RAMP = 200000 steps (0.2 s), ISO_TOL = 1e-3, ISO_UNB = 1e-3,
ISO_HOLD = 5000 steps, REC_TOL = 2.5e-3 (half of the 0.5 % asked for).
"""
import math
import os
import sys
import time

from yade import *  # noqa: F401,F403  (O, engines, Vector3, Matrix3, ...)
from yade import utils

# yade -x: __file__ is yade's launcher, sys.argv[0] this script
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
import yade_common  # noqa: E402

# ------------------------------------------------------------------ parameters
KN = 1.0e7           # N/m, normal contact stiffness (constant)
KS = 2.0e6           # N/m, tangential contact stiffness (constant)
MU = 0.4             # Coulomb friction coefficient
RHO2D = 2000.0       # kg/m^2, areal density of the discs
DAMP = 0.7           # Cundall local non-viscous damping
DT = 1.0e-6          # s, time step
P = 1.5e5            # N/m, confining stress magnitude (compression)
EPS_END = 0.10       # final axial strain 1 - Ly/Ly_ic
REC_STEP = 0.005     # record every 0.5 % of axial strain
TRACE_STEP = 0.001   # trace file every 0.1 %
BASE_RATE = 0.1      # 1/s, base axial true strain rate
LZ_OVER_RMAX = 20.0  # z period in max radii

NCTL = 10            # servo update period (steps)
TAU = 1.0e-4         # s, servo closure time (proportional part)
TI = 2.0e-3          # s, integral time
DMAX = 5.0           # 1/s, bound on the servo strain rates
N_RAMP = 200000      # steps of the isotropic target ramp
ISO_TOL = 1.0e-3     # relative stress tolerance, end of stage 1
ISO_UNB = 1.0e-3     # unbalanced force tolerance, end of stage 1
ISO_HOLD = 5000      # steps the stage-1 criteria must hold
ISO_MAX = 2000000    # steps, give up stage 1 after this
REC_TOL = 2.5e-3     # relative lateral stress error allowed at a record
HOLD_MAX = 50000     # steps, max pause at a record point


fail = yade_common.make_fail("biaxial_periodic")

# ------------------------------------------------------------------ arguments
if len(sys.argv) < 4:
    fail("usage: yade -n -x -j1 biaxial_periodic.py PACKING OUT.csv RATE_FACTOR [NAME=VALUE ...]")
PACKING, OUTCSV, RATE_FACTOR = sys.argv[1], sys.argv[2], float(sys.argv[3])
# optional overrides of the numeric parameters above, for checks only
# (e.g. DT=5e-7 TAU=1e-4); the reference runs use none.
OVERRIDES = yade_common.apply_overrides(sys.argv[4:], globals(), fail)
RATE = BASE_RATE * RATE_FACTOR
TRACECSV = os.path.splitext(OUTCSV)[0] + "_trace.csv"


# ------------------------------------------------------------------ read packing
def read_packing(path):
    box, atoms = yade_common.read_lammps_data(path, fail, "xy")
    return box, [(aid, r, x, y) for (aid, r, _, x, y, _) in atoms]


box, atoms = read_packing(PACKING)
LX0 = box["x"][1] - box["x"][0]
LY0 = box["y"][1] - box["y"][0]
RMAX = max(a[1] for a in atoms)
LZ = LZ_OVER_RMAX * RMAX
N = len(atoms)

# ------------------------------------------------------------------ scene
O.periodic = True
O.cell.hSize = Matrix3(LX0, 0, 0, 0, LY0, 0, 0, 0, LZ)
mat = O.materials.append(FrictMat(young=1e9, poisson=0.2, density=RHO2D,
                                  frictionAngle=math.atan(MU), label="disc"))
# young/poisson/density of the material are not used: kn, ks come from the
# MatchMakers below, masses and inertias are set by hand.
for (aid, r, x, y) in atoms:
    b = utils.sphere((x - box["x"][0], y - box["y"][0], 0.0), r, material=mat)
    m = RHO2D * math.pi * r * r
    b.state.mass = m
    b.state.inertia = Vector3(1, 1, 1) * 0.5 * m * r * r
    b.state.blockedDOFs = "zXY"
    O.bodies.append(b)

O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb()]),
    InteractionLoop(
        [Ig2_Sphere_Sphere_ScGeom()],
        [Ip2_FrictMat_FrictMat_FrictPhys(kn=MatchMaker(algo="val", val=KN),
                                         ks=MatchMaker(algo="val", val=KS))],
        [Law2_ScGeom_FrictPhys_CundallStrack()],
    ),
    PyRunner(command="control()", iterPeriod=NCTL, label="ctl", dead=True),
    NewtonIntegrator(damping=DAMP, label="newton"),
]
O.dt = DT


# ------------------------------------------------------------------ helpers
def cell_lx():
    return O.cell.hSize[0, 0]


def cell_ly():
    return O.cell.hSize[1, 1]


def stress2d():
    """2D Cauchy stress (N/m), tension positive."""
    return utils.getStress() * LZ


def contacts():
    return [i for i in O.interactions if i.isReal and i.geom.penetrationDepth > 0]


def n_contacts_and_mech():
    cs = contacts()
    deg = [0] * N
    for i in cs:
        deg[i.id1] += 1
        deg[i.id2] += 1
    rattlers = sum(1 for d in deg if d < 2)
    n_nr = N - rattlers
    z_mech = (2.0 * len(cs) - sum(d for d in deg if d < 2)) / n_nr if n_nr else 0.0
    return len(cs), rattlers, z_mech


def affine_stiffness():
    """(1/A) sum_c kn l^2 n_i^4 for i = x, y (N/m)."""
    kx = ky = 0.0
    for i in contacts():
        l = O.bodies[i.id1].shape.radius + O.bodies[i.id2].shape.radius - i.geom.penetrationDepth
        n = i.geom.normal
        kx += i.phys.kn * l * l * n[0] ** 4
        ky += i.phys.kn * l * l * n[1] ** 4
    a = cell_lx() * cell_ly()
    return max(kx / a, 1e3), max(ky / a, 1e3)


def dt_estimate():
    """Stiffness-based critical steps (yade_common.dt_estimate)."""
    return yade_common.dt_estimate(O.bodies, contacts(), N, 2)


# ------------------------------------------------------------------ output
COLUMNS = ["stage", "step", "time_s", "axial_strain", "sigma11_Npm", "sigma22_Npm",
           "sigma12_Npm", "stress_ratio", "J_rel", "n_contacts", "coordination",
           "rattlers", "coordination_mech", "lateral_err_rel", "unbalanced",
           "Lx_m", "Ly_m", "hold_steps"]

st = {"stage": 0, "Lx_ic": None, "Ly_ic": None, "ix": 0.0, "iy": 0.0,
      "kx": None, "ky": None, "ramp0": 0, "s0": None, "ok_since": None,
      "next_rec": 0.0, "next_trace": 0.0, "hold": 0, "holding": False,
      "rows": [], "trace": [], "t0": time.time(), "max_hold": 0,
      "max_lat_err": 0.0, "Dy": 0.0, "Dx": 0.0}


def row(stage, hold=0):
    s = stress2d()
    s11, s22, s12 = s[0, 0], s[1, 1], s[0, 1]
    nc, rat, zm = n_contacts_and_mech()
    lx, ly = cell_lx(), cell_ly()
    if st["Lx_ic"] is not None:
        ax = 1.0 - ly / st["Ly_ic"]
        jrel = lx * ly / (st["Lx_ic"] * st["Ly_ic"]) - 1.0
    else:
        ax = float("nan")
        jrel = float("nan")
    ratio = abs((s11 - s22) / (s11 + s22)) if (s11 + s22) != 0 else float("nan")
    return {"stage": stage, "step": O.iter, "time_s": O.time, "axial_strain": ax,
            "sigma11_Npm": s11, "sigma22_Npm": s22, "sigma12_Npm": s12,
            "stress_ratio": ratio, "J_rel": jrel, "n_contacts": nc,
            "coordination": 2.0 * nc / N, "rattlers": rat, "coordination_mech": zm,
            "lateral_err_rel": (s11 + P) / P, "unbalanced": utils.unbalancedForce(),
            "Lx_m": lx, "Ly_m": ly, "hold_steps": hold}


def write_csv(path, rows, header_lines):
    yade_common.write_csv(path, rows, header_lines, COLUMNS)


def log(msg):
    print("[%7.1f s, step %8d] %s" % (time.time() - st["t0"], O.iter, msg))
    sys.stdout.flush()


def show(r):
    log("%-9s eps %.4f s11 %.1f s22 %.1f s12 %.1f q/p %.4f J_rel %.5f C %d Z %.3f err %.2e unb %.1e hold %d" % (
        r["stage"], r["axial_strain"], r["sigma11_Npm"], r["sigma22_Npm"], r["sigma12_Npm"],
        r["stress_ratio"], r["J_rel"], r["n_contacts"], r["coordination"],
        r["lateral_err_rel"], r["unbalanced"], r["hold_steps"]))


# ------------------------------------------------------------------ servo
def pi_rate(err, integ, k):
    return yade_common.pi_rate(err, integ, k, TI, TAU, DMAX)


def set_velgrad(dx, dy):
    st["Dx"], st["Dy"] = dx, dy
    O.cell.velGrad = Matrix3(dx, 0, 0, 0, dy, 0, 0, 0, 0)


def control():
    s = stress2d()
    s11, s22 = s[0, 0], s[1, 1]
    dtc = NCTL * O.dt
    if st["stage"] == 1:
        f = min(1.0, (O.iter - st["ramp0"]) / float(N_RAMP))
        t11 = st["s0"][0] + f * (-P - st["s0"][0])
        t22 = st["s0"][1] + f * (-P - st["s0"][1])
        ex, ey = t11 - s11, t22 - s22
        st["ix"] += ex * dtc
        st["iy"] += ey * dtc
        set_velgrad(pi_rate(ex, st["ix"], st["kx"]), pi_rate(ey, st["iy"], st["ky"]))
        if (O.iter - st["ramp0"]) % 20000 < NCTL:
            kx, ky = affine_stiffness()
            st["kx"], st["ky"] = kx, ky
        if f >= 1.0:
            ok = (abs(s11 + P) < ISO_TOL * P and abs(s22 + P) < ISO_TOL * P
                  and utils.unbalancedForce() < ISO_UNB)
            if not ok:
                st["ok_since"] = None
            elif st["ok_since"] is None:
                st["ok_since"] = O.iter
            elif O.iter - st["ok_since"] >= ISO_HOLD:
                end_isotropic()
                return
            if O.iter - st["ramp0"] > ISO_MAX:
                fail("isotropic stage did not converge")
        if (O.iter - st["ramp0"]) % 50000 < NCTL:
            log("iso: s11 %.1f s22 %.1f s12 %.1f unb %.2e Lx %.6e Ly %.6e" % (
                s11, s22, s[0, 1], utils.unbalancedForce(), cell_lx(), cell_ly()))
        return
    if st["stage"] == 2:
        ex = -P - s11
        st["ix"] += ex * dtc
        dx = pi_rate(ex, st["ix"], st["kx"])
        ax = 1.0 - cell_ly() / st["Ly_ic"]
        lat = abs(s11 + P) / P
        if ax >= st["next_trace"] - 1e-12:
            st["trace"].append(row("biaxial"))
            st["next_trace"] += TRACE_STEP
        if ax >= st["next_rec"] - 1e-12:
            if lat > REC_TOL and not st["holding"]:
                st["holding"], st["hold"] = True, 0
            if st["holding"]:
                st["hold"] += NCTL
                if lat > 0.5 * REC_TOL and st["hold"] < HOLD_MAX:
                    set_velgrad(dx, 0.0)
                    return
            r = row("biaxial", st["hold"])
            st["rows"].append(r)
            st["max_hold"] = max(st["max_hold"], st["hold"])
            st["max_lat_err"] = max(st["max_lat_err"], abs(r["lateral_err_rel"]))
            show(r)
            st["holding"], st["hold"] = False, 0
            st["next_rec"] += REC_STEP
            if st["next_rec"] > EPS_END + 1e-9:
                st["stage"] = 3
                set_velgrad(0.0, 0.0)
                O.pause()
                return
            if len(st["rows"]) % 4 == 0:
                st["kx"], st["ky"] = affine_stiffness()
        set_velgrad(dx, -RATE)


def end_isotropic():
    st["Lx_ic"], st["Ly_ic"] = cell_lx(), cell_ly()
    r = row("isotropic")
    st["rows"].append(r)
    show(r)
    dtt, dtr = dt_estimate()
    st["dt_est"] = (dtt, dtr)
    log("stage 1 done: Lx_ic %.8e Ly_ic %.8e ; dt estimate translation %.3e rotation %.3e s (DT/min = %.2f)"
        % (st["Lx_ic"], st["Ly_ic"], dtt, dtr, DT / min(dtt, dtr)))
    st["iso_steps"] = O.iter
    st["stage"] = 2
    st["next_rec"] = 0.0
    st["next_trace"] = 0.0
    st["kx"], st["ky"] = affine_stiffness()
    st["t_biax0"] = time.time()
    st["step_biax0"] = O.iter


# ------------------------------------------------------------------ stage 0
log("packing %s: N %d Lx %.6e Ly %.6e Lz %.6e Rmax %.6e ; rate %.4g 1/s (factor %g) ; overrides: %s"
    % (PACKING, N, LX0, LY0, LZ, RMAX, RATE, RATE_FACTOR, " ".join(OVERRIDES) or "none"))
newton.dead = True
O.step()
newton.dead = False
cs = contacts()
dev = max(abs(i.phys.normalForce.norm() - KN * i.geom.penetrationDepth) for i in cs)
devs = max(abs(i.phys.kn - KN) + abs(i.phys.ks - KS) for i in cs)
log("stage 0: %d contacts; max |Fn - KN*overlap| = %.3e N (max Fn %.3e N); kn/ks deviation %.3e; tan(phi) %.4f"
    % (len(cs), dev, max(i.phys.normalForce.norm() for i in cs), devs, cs[0].phys.tangensOfFrictionAngle))
r0 = row("initial")
st["rows"].append(r0)
show(r0)
dtt, dtr = dt_estimate()
log("dt estimate (packing as read): translation %.3e s rotation %.3e s ; DT = %.1e" % (dtt, dtr, DT))

# ------------------------------------------------------------------ stages 1, 2
st["stage"] = 1
st["ramp0"] = O.iter
st["s0"] = (r0["sigma11_Npm"], r0["sigma22_Npm"])
st["kx"], st["ky"] = affine_stiffness()
log("affine stiffness kx %.3e ky %.3e N/m" % (st["kx"], st["ky"]))
ctl.dead = False
t_start = time.time()
O.run()
O.wait()
wall = time.time() - t_start
biax_steps = O.iter - st["step_biax0"]
biax_wall = time.time() - st["t_biax0"]
log("done: %d steps, wall %.1f s (biaxial %d steps, %.1f s, %.0f steps/s); max lateral err at records %.2e; max hold %d steps"
    % (O.iter, wall, biax_steps, biax_wall, biax_steps / biax_wall, st["max_lat_err"], st["max_hold"]))

hdr = [
    "YADE %s periodic biaxial reference (benchmarks/yade_periodic/biaxial_periodic.py)" % version,
    "packing %s N %d Lx0 %.10g Ly0 %.10g Lz %.10g" % (PACKING, N, LX0, LY0, LZ),
    "kn %g ks %g mu %g rho2d %g damping %g dt %g P %g rate %g (factor %g)" % (KN, KS, MU, RHO2D, DAMP, DT, P, RATE, RATE_FACTOR),
    "Lx_ic %.10g Ly_ic %.10g iso_steps %d biax_steps %d wall_s %.2f biax_wall_s %.2f" % (
        st["Lx_ic"], st["Ly_ic"], st["iso_steps"], biax_steps, wall, biax_wall),
    "dt_estimate_translation %.4g dt_estimate_rotation %.4g" % st["dt_est"],
    "overrides %s" % (" ".join(OVERRIDES) if OVERRIDES else "none"),
    "stresses in N/m (2D), tension positive; axial_strain = 1 - Ly/Ly_ic; J_rel = Lx Ly/(Lx_ic Ly_ic) - 1",
]
write_csv(OUTCSV, st["rows"], hdr)
write_csv(TRACECSV, st["trace"], hdr)
log("wrote %s and %s" % (OUTCSV, TRACECSV))
sys.stdout.flush()
os._exit(0)
