#!/usr/bin/env python3
"""A struck modal bunny from Python: load a mesh, compute a linear modal basis, precompute
the certificates, run 200 steps of a random trajectory through the self-collision query with
certificates (SSCC) and without (traditional), and plot the time per step as a PNG.

    PYTHONPATH=build/python python3 python/examples/modal_steps.py --output time_per_step.png

The trajectory: random motion in the modes whose strain energy jumps at a strike every 50
steps and then decays, so that each strike is followed by steps the certificates cannot
decide and then by steps they can.
"""

import argparse
import pathlib
import time

# sscc first: in a python3 other than the one it was built for, it makes the build
# interpreter's NumPy (and so matplotlib, installed beside it) importable.
import sscc

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt
import numpy as np

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]
STEPS = 200
STRIKE_PERIOD = 50   # steps between strikes
PEAK_NORM = 3.0      # ||q||_M just after a strike, in root radii
REST_NORM = 0.3      # ||q||_M the motion decays to, in root radii
DECAY_STEPS = 10.0   # e-folding time of the decay, in steps
PERSISTENCE = 0.9    # how much of its direction the motion keeps from one step to the next


def trajectory(weights, root_radius, rng):
    """STEPS + 1 coordinate vectors q whose weighted norm follows the strike envelope."""
    r = len(weights)
    direction = rng.standard_normal(r)
    q = []
    for k in range(STEPS + 1):
        direction = PERSISTENCE * direction + np.sqrt(1 - PERSISTENCE**2) * rng.standard_normal(r)
        since_strike = k % STRIKE_PERIOD
        envelope = REST_NORM + (PEAK_NORM - REST_NORM) * np.exp(-since_strike / DECAY_STEPS)
        scaled = envelope * root_radius * direction / np.linalg.norm(direction)  # q_hat = M^(1/2) q
        q.append(scaled / np.sqrt(weights))
    return q


def timed(query, *arguments, **options):
    begin = time.perf_counter()
    report = query(*arguments, **options)
    return report, time.perf_counter() - begin


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--mesh", default=str(REPOSITORY / "data" / "bunny15k.off"))
    parser.add_argument("--modes", type=int, default=30)
    parser.add_argument("--youngs", type=float, default=2e7, help="Pa (stiff rubber)")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--output", default="time_per_step.png")
    args = parser.parse_args()

    mesh = sscc.read_mesh(args.mesh)
    begin = time.perf_counter()
    U, weights = sscc.modal_basis(mesh, modes=args.modes, youngs=args.youngs)
    basis_seconds = time.perf_counter() - begin
    model = sscc.SubspaceModel(mesh, U, weights)
    bvh = sscc.SubspaceBvh(model)
    begin = time.perf_counter()
    certificates = sscc.Certificates.precompute(bvh)
    precompute_seconds = time.perf_counter() - begin
    detector = sscc.SelfCcd(bvh, certificates)
    print(f"{pathlib.Path(args.mesh).name} ({mesh.triangle_count} triangles): {args.modes} modes in "
          f"{basis_seconds:.1f} s, certificates in {precompute_seconds:.1f} s, root radius "
          f"{certificates.root_radius:.3g} (strain energy {certificates.root_radius**2:.3g} J)")

    q = trajectory(weights, certificates.root_radius, np.random.default_rng(args.seed))
    sscc_ms, traditional_ms, certified, colliding, agree = [], [], [], 0, 0
    for k in range(STEPS):
        fast, fast_seconds = timed(detector.query, q[k], q[k + 1])
        slow, slow_seconds = timed(detector.query, q[k], q[k + 1], use_certificates=False,
                                   use_displacement_bounds=False)
        sscc_ms.append(1e3 * fast_seconds)
        traditional_ms.append(1e3 * slow_seconds)
        certified.append(fast.stats["root_certified"])
        colliding += fast.collided
        agree += np.array_equal(fast.pairs, slow.pairs) and np.array_equal(fast.toi, slow.toi)

    mean_fast, mean_slow = np.mean(sscc_ms), np.mean(traditional_ms)
    print(f"{STEPS} steps: SSCC {mean_fast:.3f} ms/step (median {np.median(sscc_ms):.3f}), traditional "
          f"{mean_slow:.3f} ms/step, speedup {mean_slow / mean_fast:.1f}x; certified by the root "
          f"{sum(certified)}/{STEPS}; colliding steps {colliding}; reports identical on {agree}/{STEPS}")

    steps = np.arange(STEPS)
    figure, axes = plt.subplots(figsize=(8, 4.2))
    axes.semilogy(steps, traditional_ms, color="tab:red", label="traditional (no certificates)")
    axes.semilogy(steps, sscc_ms, color="tab:blue", label="SSCC")
    marked = np.array(certified)
    axes.scatter(steps[marked], np.array(sscc_ms)[marked], s=6, color="tab:blue", zorder=3,
                 label="step certified by the root")
    for strike in range(0, STEPS, STRIKE_PERIOD):
        axes.axvline(strike, color="0.8", linewidth=0.8, zorder=0)
    axes.set_xlabel("step (grey: a strike)")
    axes.set_ylabel("self-CCD time per step (ms, from Python)")
    axes.set_title(f"{pathlib.Path(args.mesh).name}, {args.modes} modes: SSCC {mean_fast:.2f} ms, "
                   f"traditional {mean_slow:.2f} ms per step")
    axes.legend(loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=3, fontsize=8)
    figure.tight_layout()
    figure.savefig(args.output, dpi=110)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
