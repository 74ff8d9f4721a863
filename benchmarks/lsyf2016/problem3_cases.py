"""The runs of [LSYF] problem 3 that problem3.py reads (run.sh problem3_*) and the set-up it
assumes: CASES, {label: directory under RESULTS}, and the groups of them that each table
compares (the band against R and the mesh, the step series, the ensembles), with problem3.prm's
geometry and load steps. Kept apart from problem3.py so that adding a run is an edit of this
file alone."""

CASES = {"local": "problem3_R0", "R = 15 mm": "problem3_R0.015", "R = 25 mm": "problem3_R0.025",
         "R = 25 mm, local elastic 584 MPa": "problem3_R0.025_le584",
         "R = 25 mm, local elastic 50 MPa": "problem3_R0.025_le50",
         "R = 15 mm, local elastic 0.5 MPa": "problem3_R0.015_le0.5",
         "R = 20 mm, local elastic 0.5 MPa": "problem3_R0.02_le0.5",
         "R = 25 mm, local elastic 0.5 MPa": "problem3_R0.025_le0.5",
         "local, 2 us step": "problem3_R0_dt2us", "local, 1 us step": "problem3_R0_dt1us",
         "local, 12x10": "problem3_R0_12x10",
         "R = 10 mm, local elastic 0.5 MPa, 12x10": "problem3_R0.01_le0.5_12x10",
         "R = 20 mm, local elastic 0.5 MPa, 12x10": "problem3_R0.02_le0.5_12x10",
         "R = 10 mm, local elastic 2 MPa, 12x10": "problem3_R0.01_le2_12x10",
         "R = 15 mm, local elastic 2 MPa, 12x10": "problem3_R0.015_le2_12x10",
         "R = 15 mm, local elastic 2 MPa": "problem3_R0.015_le2",
         "R = 20 mm, local elastic 2 MPa": "problem3_R0.02_le2",
         "R = 6.75 mm, local elastic 2 MPa, 12x15": "problem3_R0.00675_le2_12x15",
         "R = 5 mm, local elastic 2 MPa, 12x20": "problem3_R0.005_le2_12x20",
         "R = 15 mm, local elastic 2 MPa, 12x10, seed box": "problem3_R0.015_le2_12x10_box",
         "R = 10 mm, local elastic 2 MPa, 12x10, seed box": "problem3_R0.01_le2_12x10_box",
         "R = 10 mm, local elastic 2 MPa, 12x20, seed box": "problem3_R0.01_le2_12x20_box",
         "R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume": "problem3_R0.01_le2_12x10_box_own",
         "R = 10 mm, local elastic 2 MPa, 12x20, seed box, own volume": "problem3_R0.01_le2_12x20_box_own",
         "R = 15 mm, local elastic 2 MPa, 12x10, own volume": "problem3_R0.015_le2_12x10_own",
         "R = 15 mm, local elastic 2 MPa, 12x20, seed box, own volume": "problem3_R0.015_le2_12x20_box_own",
         "R = 5 mm, local elastic 2 MPa, 12x20, seed box, own volume": "problem3_R0.005_le2_12x20_box_own",
         "R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume, 1 us step":
             "problem3_R0.01_le2_12x10_box_own_dt1us",
         "R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume, 2 /s": "problem3_R0.01_le2_12x10_box_own_rate2",
         "R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume, 0.5 us step":
             "problem3_R0.01_le2_12x10_box_own_dt0.5us",
         "R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume, 1 us step, checks of 5":
             "problem3_R0.01_le2_12x10_box_own_dt1us_ci5",
         **{f"R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume, top pressure +{k} ppm":
            f"problem3_R0.01_le2_12x10_box_own_p{k}" for k in range(1, 5)},
         **{f"R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume, 0.5 us step, top pressure +{k} ppm":
            f"problem3_R0.01_le2_12x10_box_own_dt0.5us_p{k}" for k in range(1, 4)},
         "R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume, 0.2 us step":
             "problem3_R0.01_le2_12x10_box_own_dt0.2us",
         **{f"R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume, 0.2 us step, top pressure +{k} ppm":
            f"problem3_R0.01_le2_12x10_box_own_dt0.2us_p{k}" for k in range(1, 4)},
         **{f"R = {r} mm, local elastic 2 MPa, 12x10, seed box, own volume{f', top pressure +{k} ppm' if k else ''}":
            f"problem3_R{radius}_le2_12x10_box_own{f'_p{k}' if k else ''}"
            for r, radius in ((15, "0.015"), (20, "0.02")) for k in range(4)},
         "R = 20 mm, local elastic 2 MPa, 12x10, seed box": "problem3_R0.02_le2_12x10_box",
         **{f"R = {r} mm, local elastic 2 MPa, 12x10, seed box, top pressure +{k} ppm":
            f"problem3_R{radius}_le2_12x10_box_p{k}"
            for r, radius in ((10, "0.01"), (15, "0.015"), (20, "0.02")) for k in range(1, 3)},
         **{f"R = {r} mm, local elastic 2 MPa, 12x10, seed box, own volume, 1 us step":
            f"problem3_R{radius}_le2_12x10_box_own_dt1us" for r, radius in ((15, "0.015"), (20, "0.02"))},
         **{f"R = {r} mm, local elastic 2 MPa, 12x10, seed box, own volume, 1 us step, top pressure +{k} ppm":
            f"problem3_R{radius}_le2_12x10_box_own_dt1us_p{k}" for r, radius in ((15, "0.015"), (20, "0.02"))
            for k in range(1, 4)},
         # session 45's build: the last check's stress (the runs above at 2 us had the mean of two checks)
         **{f"R = {r} mm, local elastic 2 MPa, 12x10, seed box, own volume, last check":
            f"problem3_R{radius}_le2_12x10_box_own_last" for r, radius in ((15, "0.015"), (20, "0.02"))},
         # ... and at half the rate (session 46, run.sh problem3_half_rate)
         **{f"R = {r} mm, local elastic 2 MPa, 12x10, seed box, own volume, last check, 2 /s":
            f"problem3_R{radius}_le2_12x10_box_own_last_rate2" for r, radius in ((15, "0.015"), (20, "0.02"))}}
# the band width against R and the mesh: (R in mm, element height in mm, case)
# The macro step is fe2dem's default (5 us on 12x5, 2 us on 12x10 and 12x15, 1 us on 12x20) but where the
# case names it (run.sh problem3_step_cases, problem3_band_cases, problem3_scaled_cases; README,
# 'The rate, and the macro step')
RADII = [(0.0, 10.1, "local"), (15.0, 10.1, "R = 15 mm, local elastic 0.5 MPa"),
         (20.0, 10.1, "R = 20 mm, local elastic 0.5 MPa"), (25.0, 10.1, "R = 25 mm, local elastic 0.5 MPa"),
         (0.0, 5.06, "local, 12x10"), (10.0, 5.06, "R = 10 mm, local elastic 0.5 MPa, 12x10"),
         (20.0, 5.06, "R = 20 mm, local elastic 0.5 MPa, 12x10"),
         (10.0, 5.06, "R = 10 mm, local elastic 2 MPa, 12x10"), (15.0, 5.06, "R = 15 mm, local elastic 2 MPa, 12x10"),
         (15.0, 10.1, "R = 15 mm, local elastic 2 MPa"), (20.0, 10.1, "R = 20 mm, local elastic 2 MPa"),
         (6.75, 3.37, "R = 6.75 mm, local elastic 2 MPa, 12x15"), (5.0, 2.53, "R = 5 mm, local elastic 2 MPa, 12x20"),
         (15.0, 5.06, "R = 15 mm, local elastic 2 MPa, 12x10, seed box"),
         (10.0, 5.06, "R = 10 mm, local elastic 2 MPa, 12x10, seed box"),
         (10.0, 2.53, "R = 10 mm, local elastic 2 MPa, 12x20, seed box"),
         (10.0, 5.06, "R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume"),
         (10.0, 2.53, "R = 10 mm, local elastic 2 MPa, 12x20, seed box, own volume"),
         (15.0, 5.06, "R = 15 mm, local elastic 2 MPa, 12x10, own volume"),
         (15.0, 2.53, "R = 15 mm, local elastic 2 MPa, 12x20, seed box, own volume"),
         (5.0, 2.53, "R = 5 mm, local elastic 2 MPa, 12x20, seed box, own volume")]
# the band over meshes at a fixed R (run.sh problem3_fixed_r), beside the local band on two meshes:
# the profiles across the band in problem3_profiles.png
FIXED_R = ["local", "local, 12x10", "R = 10 mm, local elastic 2 MPa, 12x10, seed box",
           "R = 10 mm, local elastic 2 MPa, 12x20, seed box",
           "R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume",
           "R = 10 mm, local elastic 2 MPa, 12x20, seed box, own volume"]
# the band against R on one mesh (12x20, the seed box, own volume): problem3_profiles_r.png
AGAINST_R = ["R = 5 mm, local elastic 2 MPa, 12x20, seed box, own volume",
             "R = 10 mm, local elastic 2 MPa, 12x20, seed box, own volume",
             "R = 15 mm, local elastic 2 MPa, 12x20, seed box, own volume"]
# ... and their profiles' widths (print_profile_widths) with the one-IP seed at R = 15 mm on 12x10
PROFILE_CASES = FIXED_R + ["R = 5 mm, local elastic 2 MPa, 12x20", "R = 15 mm, local elastic 2 MPa, 12x10",
                           "R = 15 mm, local elastic 2 MPa, 12x10, own volume",
                           "R = 15 mm, local elastic 2 MPa, 12x20, seed box, own volume",
                           "R = 5 mm, local elastic 2 MPa, 12x20, seed box, own volume"]
# the banded answer's convergence (run.sh problem3_converged): the reference (default macro step 2 us,
# 4 /s) and the same case at half and a quarter of the macro step (the quarter with servo checks of 5
# DEM steps, not 10), at half the step with checks of 5, and at half the rate
CONVERGED = ("R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume",
             "R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume, 1 us step",
             "R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume, 0.5 us step",
             "R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume, 1 us step, checks of 5",
             "R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume, 2 /s")
# ... and at a tenth of the default step (0.2 us = 2 DEM steps, servo checks of 2; run.sh problem3_fine_step)
FINE_STEP = "R = 10 mm, local elastic 2 MPa, 12x10, seed box, own volume, 0.2 us step"
# ... and the reference with the top's pressure 1-4 parts per million higher, the quarter step with 1-3
# (run.sh problem3_perturbed) and the tenth with 1-3 (problem3_fine_step): the scatter at one step and
# rate, {step: (unperturbed, perturbed)}, from the largest step to the smallest
ENSEMBLES = {step: (base, tuple(k for k in CASES if k.startswith(base + ", top pressure")))
             for step, base in (("2 us", CONVERGED[0]), ("0.5 us", CONVERGED[2]), ("0.2 us", FINE_STEP))}
PERTURBED = sum((e[1] for e in ENSEMBLES.values()), ())
# ... and the 2 us ensemble at R = 15 and 20 mm beside R = 10 mm's, with each RVE's own volume (run.sh
# problem3_against_r) and with the averaged one (problem3_against_r_averaged; session 44): the band's
# width against R from ensemble means, {family: {R in mm: (unperturbed, perturbed)}}
R_FAMILIES = {family: {r: (base, tuple(k for k in CASES if k.startswith(base + ", top pressure")))
                       for r, base in ((r, f"R = {r:g} mm, local elastic 2 MPa, 12x10, seed box{suffix}")
                                       for r in (10.0, 15.0, 20.0))}
              for family, suffix in (("own volume", ", own volume"), ("averaged volume", ""))}
# ... and own volume at one check per macro step, where the mean of a step's checks (fe2dem before session
# 45) and the last check's stress (since) are the same bits: R = 10 mm at 0.2 us (checks of 2), R = 15
# and 20 mm at 1 us (run.sh problem3_own_half_step, problem3_against_r_half_step)
R_FAMILIES["own volume, one check per step"] = {
    r: (base, tuple(k for k in CASES if k.startswith(base + ", top pressure")))
    for r, base in ((r, f"R = {r:g} mm, local elastic 2 MPa, 12x10, seed box, own volume, {step} step")
                    for r, step in ((10.0, "0.2 us"), (15.0, "1 us"), (20.0, "1 us")))}
# the ensembles' macro step, where not fe2dem's default 2 us on 12x10
FAMILY_STEP = {"own volume, one check per step": "0.2 us at R = 10 mm, 1 us at 15 and 20 mm"}
APPLIED = 4.16e5  # Pa, the top's vertical stress (problem3.prm)
# ... and own volume at 1 us, (R in mm, case) (run.sh problem3_own_half_step; R = 10 mm's is CONVERGED[1])
HALF_STEP = [(10.0, CONVERGED[1]),
             *((r, f"R = {r:g} mm, local elastic 2 MPa, 12x10, seed box, own volume, 1 us step") for r in (15.0, 20.0)),
             (20.0, "R = 20 mm, local elastic 2 MPa, 12x10, seed box, own volume, 1 us step, top pressure +1 ppm")]
# ... and own volume at the default 2 us with the last check's stress (session 45's build), at 4 and 2 /s
# (run.sh problem3_last_check, problem3_half_rate): (R in mm, case, label)
LAST_CHECK = [(r, f"R = {r:g} mm, local elastic 2 MPa, 12x10, seed box, own volume, last check{suffix}", label)
              for r in (15.0, 20.0) for suffix, label in (("", "2 us, 4 /s"), (", 2 /s", "2 us, 2 /s"))]
# the R = 20 mm own-volume case for its first 1 % of shear, one ingredient changed at a time (run.sh
# problem3_hourglass_probe; two rows, so not in CASES): {label: directory}
PROBES = {"R = 20 mm, own volume, seed box, 2 us (as problem3_against_r)": "probe_R0.02_own_box",
          "... without the seed": "probe_R0.02_own_no_seed",
          "... without C_e (total strain)": "probe_R0.02_own_box_total_strain",
          "... with the averaged volume": "probe_R0.02_averaged_box",
          "... at 1 us": "probe_R0.02_own_box_dt1us",
          "as run, 2 us, with the last check's stress (session 45's build)": "probe_R0.02_own_box_last"}
BACKWARDS = -0.01  # a shear increment below this over the last BAND_ROWS rows: an IP shearing backwards
# the band's directions in simple shear: along the shear, within 20 degrees of x (the local runs' band
# is at 4 degrees); among all directions the finder can return a hot spot around the weak RVE
ALONG_X = list(range(0, 21)) + list(range(160, 180))
NU_E = 0.2  # C_e's Poisson ratio (run.sh local_elastic)
HEIGHT, SHEAR = 0.0506, 0.08           # the top's displacement is SHEAR * HEIGHT at the end
LOAD_STEPS = 16                        # problem3.prm: rows at SHEAR * step / LOAD_STEPS
BAND_ROWS = 4
OFF_BAND = 0.012  # m from the weak IP's row: outside the local runs' bands on both meshes
