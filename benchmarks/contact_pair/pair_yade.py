# -*- coding: utf-8 -*-
"""
pair_yade.py -- YADE twin of pair.liggghts: one sphere-sphere contact under
fully prescribed kinematics, Law2_ScGeom_FrictPhys_CundallStrack with
constant kn, ks (MatchMaker algo 'val') on Ig2_Sphere_Sphere_ScGeom.

    yade -n -x -j1 pair_yade.py OUT.csv [AGR [N3B]]

AGR = 1 (default) or 0: Ig2_Sphere_Sphere_ScGeom.avoidGranularRatcheting
(YADE's default is True: the relative velocity at the contact is
alpha (v2 - v1) - w2 x (R2 n) - w1 x (R1 n), alpha = (R1+R2)/(R1+R2-delta);
False: v2 - v1 + w2 x (x_c - x2) - w1 x (x_c - x1), x_c the contact point).

Both bodies have blockedDOFs 'xyzXYZ'.  A PyRunner ("drive", first engine
after ForceResetter, every step) sets, for iteration k, pos = X(k) (the same
analytic path LIGGGHTS' fix move follows), vel = the velocity LIGGGHTS' fix
move gives at step k, and angVel = the prescribed spin.  NewtonIntegrator
(damping 0, no gravity) then moves the blocked bodies with these velocities;
"drive" records the largest distance between the position Newton reached and
the prescribed X(k) before it resets pos (printed at the end, leaving out the
first step of each phase, where Newton still moved with the previous phase's
velocity: the one-step lag of setting velocities for the interval (k-1, k]).  So the contact law at
iteration k sees exactly the positions and velocities LIGGGHTS' pair style
sees at step k.  A second PyRunner after InteractionLoop writes the force on
body 1 (sphere 2) every EVERY iterations (k = 0, 100, ...).
N3B > 0 inserts phase 3.5 (N3B steps): sphere 2 slides back +y by 1e-5 m, so
that phases 4-6 start from an elastic (not sliding) tangential force.
Phases and numbers: see pair.liggghts (same names).
"""
import math
import sys

from yade import *  # noqa: F401,F403
from yade import utils

OUT = sys.argv[1] if len(sys.argv) > 1 else "results/yade.csv"
AGR = bool(int(sys.argv[2])) if len(sys.argv) > 2 else True
N3B = int(sys.argv[3]) if len(sys.argv) > 3 else 0   # steps of the optional phase 3.5 (0: none)
R, RHO, KN, KS, MU, DT = 1e-3, 2650.0, 1e5, 2.5e4, 0.5, 1e-7
GAP0, DELTA = 1e-6, 1e-5
EVERY = 100
# (phase id, steps); phase 3.5 (optional): slide back +y by 1e-5 (elastic unloading)
PH = [(1, 11000), (2, 8000), (3, 12000)] + ([(3.5, N3B)] if N3B > 0 else []) \
    + [(4, 10000), (5, 10000), (6, 10000)]
NSTEP = dict(PH)
K = [0]
for _, n in PH:
    K.append(K[-1] + n)          # PH[i] covers steps K[i]+1 .. K[i+1]
NTOT = K[-1]

V1 = (GAP0 + DELTA) / (NSTEP[1] * DT)
V2 = 4e-5 / (NSTEP[2] * DT)
V3 = 6e-5 / (NSTEP[3] * DT)
V3B = 1e-5 / (N3B * DT) if N3B > 0 else 0.0
W4 = 2.0 * math.pi / (12 * NSTEP[4] * DT)   # as fix move rotate: 2 pi / period
W5 = math.pi / 6 / (NSTEP[5] * DT)
W6 = math.pi / 2 / (NSTEP[6] * DT)
X0 = 2 * R + GAP0


def step_phase(k):
    for i in range(len(PH)):
        if k <= K[i + 1]:
            return i
    return len(PH) - 1


def phase(k):
    return PH[step_phase(k)][0]


def kin_rel(p, S, t, n6):
    """(pos2, vel2, angVel1_z, angVel2) at time t into phase p that starts at S."""
    if p == 1:
        return (S[0] + (-V1) * t, S[1]), (-V1, 0.0), 0.0, (0.0, 0.0, 0.0)
    if p == 2:
        return (S[0], S[1] + V2 * t), (0.0, V2), 0.0, (0.0, 0.0, 0.0)
    if p == 3:
        return (S[0], S[1] + (-V3) * t), (0.0, -V3), 0.0, (0.0, 0.0, 0.0)
    if p == 3.5:
        return (S[0], S[1] + V3B * t), (0.0, V3B), 0.0, (0.0, 0.0, 0.0)
    if p == 4:   # as fix move rotate: x = a cos + (z x a) sin, v = W z x x, omega = W z
        c, s = math.cos(W4 * t), math.sin(W4 * t)
        x, y = S[0] * c - S[1] * s, S[0] * s + S[1] * c
        return (x, y), (-W4 * y, W4 * x), W4, (0.0, 0.0, W4)
    if p == 5:   # as pair.liggghts' fix move variable: x = x0 + dx(t)
        c, s = math.cos(W5 * t), math.sin(W5 * t)
        x = S[0] + S[0] * (c - 1) - S[1] * s
        y = S[1] + S[0] * s + S[1] * (c - 1)
        vx = -W5 * (S[0] * s + S[1] * c)
        vy = W5 * (S[0] * c - S[1] * s)
        return (x, y), (vx, vy), 0.0, (0.0, 0.0, 2 * W5)
    return S, (0.0, 0.0), 0.0, (W6 * n6[0], W6 * n6[1], 0.0)


# start position of every phase (end of the previous one)
START = [(X0, 0.0)]
for i, (p, n) in enumerate(PH):
    START.append(kin_rel(p, START[i], n * DT, (0.0, 0.0))[0])
N6 = [(x / math.hypot(x, y), y / math.hypot(x, y)) for (x, y) in [START[len(PH) - 1]]][0]


def kin(k):
    """(phase, pos2, vel2, angVel1_z, angVel2) at step k, as LIGGGHTS' fix move sets them."""
    if k == 0:
        return 0, (X0, 0.0), (0.0, 0.0), 0.0, (0.0, 0.0, 0.0)
    i = step_phase(k)
    return (PH[i][0],) + kin_rel(PH[i][0], START[i], (k - K[i]) * DT, N6)


mat = O.materials.append(FrictMat(young=1e9, poisson=0.2, density=RHO,
                                  frictionAngle=math.atan(MU), label="grain"))
b1 = O.bodies.append(utils.sphere((0, 0, 0), R, material=mat))
b2 = O.bodies.append(utils.sphere((X0, 0, 0), R, material=mat))
for b in O.bodies:
    b.state.blockedDOFs = "xyzXYZ"

st = {"maxdev": 0.0, "rows": []}


def drive():
    k = O.iter
    p, x2, v2, w1, w2 = kin(k)
    B1, B2 = O.bodies[b1], O.bodies[b2]
    if k > 1 and phase(k) == phase(k - 1):
        dev = max((B2.state.pos - Vector3(x2[0], x2[1], 0)).norm(), B1.state.pos.norm())
        st["maxdev"] = max(st["maxdev"], dev)
    B1.state.pos = Vector3(0, 0, 0)
    B1.state.vel = Vector3(0, 0, 0)
    B1.state.angVel = Vector3(0, 0, w1)
    B2.state.pos = Vector3(x2[0], x2[1], 0)
    B2.state.vel = Vector3(v2[0], v2[1], 0)
    B2.state.angVel = Vector3(*w2)


def record():
    k = O.iter
    B1, B2 = O.bodies[b1], O.bodies[b2]
    f = O.forces.f(b2)
    br = B2.state.pos - B1.state.pos
    n = br / br.norm()
    fn = f.dot(n)
    ft = f - fn * n
    w = B2.state.angVel
    st["rows"].append([k, k * DT, phase(k) if k else 0.0] + list(B1.state.pos) + list(B2.state.pos)
                      + list(w) + list(f) + [fn] + list(ft) + [ft.norm()])


O.engines = [
    ForceResetter(),
    PyRunner(command="drive()", iterPeriod=1, label="drv"),
    InsertionSortCollider([Bo1_Sphere_Aabb()]),
    InteractionLoop(
        [Ig2_Sphere_Sphere_ScGeom(avoidGranularRatcheting=AGR)],
        [Ip2_FrictMat_FrictMat_FrictPhys(kn=MatchMaker(algo="val", val=KN),
                                         ks=MatchMaker(algo="val", val=KS))],
        [Law2_ScGeom_FrictPhys_CundallStrack()],
    ),
    PyRunner(command="record()", iterPeriod=EVERY, label="rec"),
    NewtonIntegrator(damping=0.0, gravity=(0, 0, 0), label="newton"),
]
O.dt = DT
O.run(NTOT + 1, True)

i = O.interactions[b1, b2]
print("YADE %s: avoidGranularRatcheting %s, kn %g ks %g tan(phi) %g" % (
    version, O.engines[3].geomDispatcher.functors[0].avoidGranularRatcheting,
    i.phys.kn, i.phys.ks, i.phys.tangensOfFrictionAngle))
print("largest |Newton-moved pos - prescribed pos| = %.3g m" % st["maxdev"])
cols = "step,time,phase,x1,y1,z1,x2,y2,z2,wx2,wy2,wz2,fx2,fy2,fz2,fn,ftx,fty,ftz,ft"
with open(OUT, "w") as fh:
    fh.write(cols + "\n")
    for r in st["rows"]:
        if r[0] == 0:
            continue
        fh.write("%d,%.17g,%g," % (r[0], r[1], r[2]) + ",".join("%.17g" % v for v in r[3:]) + "\n")
print("wrote %s (%d rows)" % (OUT, len(st["rows"]) - 1))
