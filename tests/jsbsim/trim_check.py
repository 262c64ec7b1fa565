#!/usr/bin/env python3
"""Flies a datcom-rs JSBSim export: loads the aircraft, trims it in pitch, reads JSBSim's
aerodynamic functions and forces at the trim angle of attack (and at other angles asked for),
then simulates a few seconds and checks that every state stays finite.

Used by tests/jsbsim.rs (which compares the figures with datcom-rs's own coefficients); it can
also be run by hand:

    datcom-rs export jsbsim namelists/example-uav.dcm --aircraft /tmp/jsb/aircraft --name uav
    python3 tests/jsbsim/trim_check.py --root /tmp/jsb --model uav \
        --altitude-ft 0 --speed-fps 100.4 --alpha-range-deg=-4,12 --out /tmp/jsb/check.json

Trim: JSBSim's own trim (simulation/do_simple_trim = 1, full) needs thrust, which the exported
glider has none of; when it fails, the trim angle is where JSBSim's steady pitching moment
(no pitch rate, no alpha-dot) vanishes: bisection over the table's angles of attack, each angle
set as an initial condition and evaluated by run_ic. Without a zero in the range, the angle of
least |moment|. The simulation then starts in the steady glide at that angle (the speed where
the aerodynamic force equals the weight, the glide path angle from lift and drag).

Output (--out, JSON): the JSBSim version, the trim (method and angle), one sample per angle
(kind "trim", then "alpha" for the other angles, then "rates": the trim angle with sideslip and
body rates, so that every lateral and rate term is non-zero) with the flight state, every aero/coefficient function, the body-axis aerodynamic forces (lbf) and
moments (lbf.ft), and the simulation's summary.
"""

import argparse
import json
import math
import sys

import jsbsim

# The terrain is put this far below the initial altitude so that a short glide never meets it
# (decks often fly at sea level, where JSBSim's ground would otherwise be).
TERRAIN_BELOW_FT = 5000.0

STATE = [
    "velocities/u-fps",
    "velocities/v-fps",
    "velocities/w-fps",
    "velocities/p-rad_sec",
    "velocities/q-rad_sec",
    "velocities/r-rad_sec",
    "attitude/phi-rad",
    "attitude/theta-rad",
    "attitude/psi-rad",
    "position/h-sl-ft",
    "position/lat-gc-rad",
    "position/long-gc-rad",
]

FLIGHT = {
    "alpha_rad": "aero/alpha-rad",
    "beta_rad": "aero/beta-rad",
    "alphadot_rad_sec": "aero/alphadot-rad_sec",
    "mach": "velocities/mach",
    "vt_fps": "velocities/vt-fps",
    "qbar_psf": "aero/qbar-psf",
    "p_rad_sec": "velocities/p-aero-rad_sec",
    "q_rad_sec": "velocities/q-aero-rad_sec",
    "r_rad_sec": "velocities/r-aero-rad_sec",
    "bi2vel": "aero/bi2vel",
    "ci2vel": "aero/ci2vel",
    "sw_sqft": "metrics/Sw-sqft",
    "bw_ft": "metrics/bw-ft",
    "cbarw_ft": "metrics/cbarw-ft",
    "fbx_lbs": "forces/fbx-aero-lbs",
    "fby_lbs": "forces/fby-aero-lbs",
    "fbz_lbs": "forces/fbz-aero-lbs",
    "l_lbsft": "moments/l-aero-lbsft",
    "m_lbsft": "moments/m-aero-lbsft",
    "n_lbsft": "moments/n-aero-lbsft",
}


# The sideslip and body rates of the "rates" sample, which makes every lateral and rate term of
# the export non-zero so that each can be read back.
RATES_SAMPLE = {"beta_deg": 2.0, "p": 0.10, "q": 0.05, "r": 0.08}
NO_RATES = {"beta_deg": 0.0, "p": 0.0, "q": 0.0, "r": 0.0}


def set_ic(fdm, args, alpha_deg, gamma_deg=0.0, rates=None):
    rates = rates or NO_RATES
    fdm["ic/h-sl-ft"] = args.altitude_ft
    fdm["ic/terrain-elevation-ft"] = args.altitude_ft - TERRAIN_BELOW_FT
    fdm["ic/vt-fps"] = args.speed_fps
    fdm["ic/beta-deg"] = rates["beta_deg"]
    fdm["ic/phi-deg"] = 0.0
    fdm["ic/psi-true-deg"] = 0.0
    fdm["ic/p-rad_sec"] = rates["p"]
    fdm["ic/q-rad_sec"] = rates["q"]
    fdm["ic/r-rad_sec"] = rates["r"]
    fdm["ic/gamma-deg"] = gamma_deg
    fdm["ic/alpha-deg"] = alpha_deg
    fdm.run_ic()


def sample(fdm, args, kind, alpha_deg, rates=None):
    set_ic(fdm, args, alpha_deg, rates=rates)
    out = {"kind": kind}
    out.update({k: fdm[p] for k, p in FLIGHT.items()})
    names = [
        line.split(" ")[0]
        for line in fdm.query_property_catalog("aero/coefficient/").splitlines()
        if line.strip()
    ]
    out["functions"] = {n.rsplit("/", 1)[1]: fdm[n] for n in names}
    return out


def pitching_moment(fdm, args, alpha_deg):
    """JSBSim's aerodynamic pitching moment about the c.g. (the AERORP) at alpha with no pitch
    rate, less its alpha-dot term: right after run_ic JSBSim's alpha-dot comes from the initial
    condition's unbalanced forces, while in steady flight it is zero."""
    set_ic(fdm, args, alpha_deg)
    adot = "aero/coefficient/Cmadot"
    return fdm["moments/m-aero-lbsft"] - (fdm[adot] if fdm.get_property_manager().hasNode(adot) else 0.0)


def trim(fdm, args):
    set_ic(fdm, args, 0.5 * (args.alpha_lo + args.alpha_hi))
    try:
        fdm["simulation/do_simple_trim"] = 1
        return {"method": "JSBSim full trim", "alpha_deg": fdm["aero/alpha-deg"]}
    except jsbsim.TrimFailureError:
        pass
    steps = max(2, int(round(args.alpha_hi - args.alpha_lo)) * 2)
    grid = [args.alpha_lo + (args.alpha_hi - args.alpha_lo) * i / steps for i in range(steps + 1)]
    moments = [pitching_moment(fdm, args, a) for a in grid]
    for (a0, m0), (a1, m1) in zip(zip(grid, moments), zip(grid[1:], moments[1:])):
        if m0 == 0.0:
            return {"method": "pitching moment zero (JSBSim trim failed: no thrust)", "alpha_deg": a0}
        if (m0 > 0.0) != (m1 > 0.0):
            lo, hi, mlo = a0, a1, m0
            for _ in range(60):
                mid = 0.5 * (lo + hi)
                mm = pitching_moment(fdm, args, mid)
                if (mm > 0.0) == (mlo > 0.0):
                    lo, mlo = mid, mm
                else:
                    hi = mid
            return {
                "method": "pitching moment zero by bisection (JSBSim full trim failed: no thrust)",
                "alpha_deg": 0.5 * (lo + hi),
            }
    best = min(zip(grid, moments), key=lambda am: abs(am[1]))
    return {
        "method": "least |pitching moment| in the table's range (no zero; JSBSim trim failed)",
        "alpha_deg": best[0],
    }


def simulate(fdm, args, trim_sample, alpha_deg):
    f = trim_sample["functions"]
    lift, drag = f.get("CL", 0.0), f.get("CD", 0.0)
    glide = -math.degrees(math.atan2(drag, lift)) if lift > 0.0 else 0.0
    weight = fdm["inertia/weight-lbs"]
    force = math.hypot(lift, drag)
    speed = trim_sample["vt_fps"] * math.sqrt(weight / force) if force > 0.0 else args.speed_fps
    glide_args = argparse.Namespace(**vars(args))
    glide_args.speed_fps = speed
    set_ic(fdm, glide_args, alpha_deg, glide)
    h0 = fdm["position/h-sl-ft"]
    summary = {
        "seconds": args.seconds,
        "speed_fps": speed,
        "gamma_deg": glide,
        "steps": 0,
        "finite": True,
        "first_non_finite": None,
        "h_min_ft": h0,
        "h_max_ft": h0,
    }
    while fdm.get_sim_time() < args.seconds:
        if not fdm.run():
            summary["stopped_at_s"] = fdm.get_sim_time()
            break
        summary["steps"] += 1
        for p in STATE:
            v = fdm[p]
            if not math.isfinite(v):
                summary["finite"] = False
                summary["first_non_finite"] = {"property": p, "time_s": fdm.get_sim_time()}
                return summary
        h = fdm["position/h-sl-ft"]
        summary["h_min_ft"] = min(summary["h_min_ft"], h)
        summary["h_max_ft"] = max(summary["h_max_ft"], h)
    summary["final"] = {p: fdm[p] for p in STATE}
    summary["time_s"] = fdm.get_sim_time()
    return summary


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--root", required=True, help="folder holding aircraft/<model>/<model>.xml")
    ap.add_argument("--model", required=True)
    ap.add_argument("--altitude-ft", type=float, required=True)
    ap.add_argument("--speed-fps", type=float, required=True)
    ap.add_argument("--alpha-range-deg", required=True, help="lo,hi: where to look for the trim")
    ap.add_argument("--alphas-deg", default="", help="more angles to sample, comma-separated")
    ap.add_argument("--seconds", type=float, default=10.0)
    ap.add_argument("--out", required=True)
    args = ap.parse_args()
    args.alpha_lo, args.alpha_hi = (float(x) for x in args.alpha_range_deg.split(","))

    fdm = jsbsim.FGFDMExec(args.root)
    fdm.set_debug_level(0)
    if not fdm.load_model(args.model):
        print(f"JSBSim could not load {args.model} from {args.root}", file=sys.stderr)
        return 1
    t = trim(fdm, args)
    trim_sample = sample(fdm, args, "trim", t["alpha_deg"])
    others = [float(a) for a in args.alphas_deg.split(",") if a.strip()]
    samples = [trim_sample] + [sample(fdm, args, "alpha", a) for a in others]
    samples.append(sample(fdm, args, "rates", t["alpha_deg"], RATES_SAMPLE))
    result = {
        "jsbsim_version": jsbsim.__version__,
        "trim": t,
        "samples": samples,
        "simulation": simulate(fdm, args, trim_sample, t["alpha_deg"]),
    }
    with open(args.out, "w") as f:
        json.dump(result, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
