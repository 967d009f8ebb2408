#!/usr/bin/env python3
"""Batches on a Dask cluster: the certificates precomputed in shards and merged into the
certificate file one precomputation writes, byte for byte; and the kernels' check against the
exact reference split into seed ranges whose counts add up (docs/cluster.md).

    PYTHONPATH=build/python python3 python/examples/dask_precompute.py \\
        --mesh data/bunny15k.off --shards 8 --output bunny15k.sscc
    PYTHONPATH=build/python python3 python/examples/dask_precompute.py --kernels 1:101 --ranges 10

By default the tasks run on a LocalCluster of --workers processes on this machine, on the
loopback interface only; with --scheduler tcp://HOST:8786 they run on that cluster's workers
(started with dask-scheduler and dask-worker), which need the sscc package, the mesh (and
basis and weights) files, and for the kernels the sscc binary, at the same paths. Each shard
task rebuilds the model and hierarchy from the files (the build is deterministic, and the
shards' keys check that every worker built the same tree) and returns its shard's bytes, so
nothing but the inputs needs a shared filesystem.
"""

import argparse
import os
import pathlib
import subprocess
import time

import numpy as np

import sscc

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]


def load_bvh(mesh, basis="polynomial:27", weights=None):
    """The hierarchy of a model, as `sscc precompute --mesh --basis --weights` builds it: basis
    'polynomial:R' or a basis file, weights from a file or all ones."""
    triangles = sscc.read_mesh(mesh)
    if basis.startswith("polynomial:"):
        u = sscc.polynomial_basis(triangles, int(basis.split(":", 1)[1]))
    else:
        u = sscc.read_basis(basis)
    w = np.loadtxt(weights, ndmin=1).ravel() if weights else np.ones(u.shape[1])
    return sscc.SubspaceBvh(sscc.SubspaceModel(triangles, u, w))


def shard_task(mesh, basis, weights, index, count, epsilon, global_radius_scale):
    """One shard, on a worker: its bytes (CertificateShard.to_bytes)."""
    bvh = load_bvh(mesh, basis, weights)
    shard = sscc.Certificates.precompute_shard(bvh, index, count, epsilon=epsilon,
                                               global_radius_scale=global_radius_scale)
    return shard.to_bytes()


def precompute_on(client, mesh, basis="polynomial:27", weights=None, shards=4, epsilon=0.1,
                  global_radius_scale=1.0):
    """The certificates of the model, its shards computed as tasks on the client's cluster and
    merged here. Files are passed by absolute path: the workers open them."""
    mesh = str(pathlib.Path(mesh).resolve())
    if not basis.startswith("polynomial:"):
        basis = str(pathlib.Path(basis).resolve())
    weights = str(pathlib.Path(weights).resolve()) if weights else None
    futures = [client.submit(shard_task, mesh, basis, weights, i, shards, epsilon, global_radius_scale)
               for i in range(shards)]
    parts = client.gather(futures)
    bvh = load_bvh(mesh, basis, weights)
    return sscc.Certificates.merge(bvh, [sscc.CertificateShard.from_bytes(part, bvh) for part in parts])


def default_sscc_binary():
    build = pathlib.Path(os.environ.get("SSCC_BUILD_DIR", REPOSITORY / "build"))
    return str(build / "bin" / "sscc")


def kernel_range_task(sscc_binary, begin, end, per_seed):
    """`sscc kernels --seeds begin:end` on a worker: {line label: (queries, contacts,
    disagreements)} for its random and near-degenerate queries of each kind."""
    result = subprocess.run([sscc_binary, "kernels", "--seeds", f"{begin}:{end}", "--per-seed", str(per_seed),
                             "--quiet"], capture_output=True, text=True)
    counts = {}
    for line in result.stdout.splitlines():
        label, _, values = line.partition(": ")
        if label.startswith(("random ", "near-degenerate ")):
            fields = dict(item.split("=") for item in values.split())
            counts[label] = (int(fields["queries"]), int(fields["contacts"]), int(fields["disagreements"]))
    if result.returncode not in (0, 1) or len(counts) != 4:  # 1: disagreements, counted
        raise RuntimeError(f"sscc kernels --seeds {begin}:{end} failed ({result.returncode}): {result.stderr}")
    return counts


def seed_ranges(begin, end, ranges):
    """begin..end-1 cut into `ranges` consecutive ranges of nearly equal length."""
    cuts = [begin + (end - begin) * i // ranges for i in range(ranges + 1)]
    return [(a, b) for a, b in zip(cuts, cuts[1:]) if a < b]


def validate_kernels_on(client, begin, end, ranges, per_seed=1000, sscc_binary=None):
    """The kernels' check of seeds begin..end-1, as `ranges` tasks; the counts summed."""
    binary = sscc_binary or default_sscc_binary()
    futures = [client.submit(kernel_range_task, binary, a, b, per_seed) for a, b in seed_ranges(begin, end, ranges)]
    total = {}
    for counts in client.gather(futures):
        for label, values in counts.items():
            total[label] = tuple(x + y for x, y in zip(total.get(label, (0, 0, 0)), values))
    return total


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mesh", help="the model's mesh (OFF, OBJ or PLY)")
    parser.add_argument("--basis", default="polynomial:27", help="polynomial:R or a basis file (default polynomial:27)")
    parser.add_argument("--weights", help="a weights file (default all ones)")
    parser.add_argument("--shards", type=int, default=4, help="shards of the precomputation (default 4)")
    parser.add_argument("--epsilon", type=float, default=0.1)
    parser.add_argument("--global-scale", type=float, default=1.0)
    parser.add_argument("--output", default="certificates.sscc", help="the certificate file written")
    parser.add_argument("--kernels", metavar="A:B", help="instead: the kernels' check of seeds A..B-1")
    parser.add_argument("--ranges", type=int, default=8, help="with --kernels: tasks (default 8)")
    parser.add_argument("--per-seed", type=int, default=1000, help="with --kernels: random queries per seed and kind")
    parser.add_argument("--sscc", default=default_sscc_binary(), help="with --kernels: the sscc binary")
    parser.add_argument("--scheduler", help="a running cluster's scheduler, tcp://HOST:PORT (default: a LocalCluster)")
    parser.add_argument("--workers", type=int, default=2, help="the LocalCluster's worker processes (default 2)")
    args = parser.parse_args()
    if not args.kernels and not args.mesh:
        parser.error("give --mesh FILE (certificates) or --kernels A:B")

    from dask.distributed import Client, LocalCluster

    if args.scheduler:
        client = Client(args.scheduler)
    else:
        cluster = LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True, host="127.0.0.1",
                               dashboard_address=None)
        client = Client(cluster)
    with client:
        start = time.perf_counter()
        if args.kernels:
            begin, end = (int(x) for x in args.kernels.split(":"))
            total = validate_kernels_on(client, begin, end, args.ranges, args.per_seed, args.sscc)
            for label, (queries, contacts, disagreements) in sorted(total.items()):
                print(f"{label}: queries={queries} contacts={contacts} disagreements={disagreements}")
            disagreements = sum(values[2] for values in total.values())
            print(f"kernels: seeds={args.kernels} queries={sum(v[0] for v in total.values())} "
                  f"disagreements={disagreements} seconds={time.perf_counter() - start:.1f}")
            raise SystemExit(1 if disagreements else 0)
        certificates = precompute_on(client, args.mesh, args.basis, args.weights, args.shards, args.epsilon,
                                     args.global_scale)
        certificates.write(args.output)
        print(f"certificates: {args.shards} shards merged into {args.output}, root radius "
              f"{certificates.root_radius:.6g}, {time.perf_counter() - start:.1f} s")


if __name__ == "__main__":
    main()
