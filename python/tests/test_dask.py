"""Batches on a Dask LocalCluster (python/examples/dask_precompute.py): the certificates
precomputed in shards merge into the file one precomputation writes, byte for byte, and the
kernels' check split into seed ranges adds up to one run's counts.

dask.distributed comes from Debian (python3-distributed, installed by scripts/setup.sh).
Without it these tests are skipped, except where SSCC_REQUIRE_DASK=1 (scripts/test.sh, CI):
there a missing Dask fails them."""

import os
import pathlib
import sys

import pytest

import sscc
from conftest import REPOSITORY

if os.environ.get("SSCC_REQUIRE_DASK") == "1":
    import distributed  # noqa: F401 (CI: Dask must be there)
else:
    pytest.importorskip("distributed", reason="dask.distributed is not installed (Debian: python3-distributed)")

from dask.distributed import Client, LocalCluster  # noqa: E402

EXAMPLES = REPOSITORY / "python" / "examples"
sys.path.insert(0, str(EXAMPLES))
import dask_precompute  # noqa: E402

MESH = REPOSITORY / "data" / "bunny1k.off"
BASIS = "polynomial:9"


@pytest.fixture(scope="module")
def client():
    # Worker processes import the example's module by name: its folder on their path.
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("PYTHONPATH", os.pathsep.join([str(EXAMPLES), os.environ.get("PYTHONPATH", "")]))
        with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                          dashboard_address=None) as cluster, Client(cluster) as dask_client:
            yield dask_client


def test_shards_on_a_local_cluster_merge_into_the_single_process_file(client, tmp_path):
    bvh = dask_precompute.load_bvh(str(MESH), BASIS)
    single = tmp_path / "single.sscc"
    sscc.Certificates.precompute(bvh).write(str(single))
    merged = tmp_path / "merged.sscc"
    dask_precompute.precompute_on(client, MESH, BASIS, shards=3).write(str(merged))
    assert merged.read_bytes() == single.read_bytes()


def test_shard_bytes_are_checked_against_the_hierarchy(tmp_path):
    bvh = dask_precompute.load_bvh(str(MESH), BASIS)
    data = dask_precompute.shard_task(str(MESH), BASIS, None, 1, 2, 0.1, 1.0)
    shard = sscc.CertificateShard.from_bytes(data, bvh)
    assert (shard.index, shard.count) == (1, 2)
    other = dask_precompute.load_bvh(str(MESH), "polynomial:3")
    with pytest.raises(OSError, match="stale"):
        sscc.CertificateShard.from_bytes(data, other)
    with pytest.raises(OSError, match="checksum"):
        sscc.CertificateShard.from_bytes(data[:40] + bytes([data[40] ^ 1]) + data[41:], bvh)
    with pytest.raises(ValueError, match="shards missing: 0/2"):
        sscc.Certificates.merge(bvh, [shard])
    path = tmp_path / "shard.sscc-part"
    shard.write(str(path))
    assert sscc.CertificateShard.read(str(path), bvh).to_bytes() == data


def test_kernel_seed_ranges_on_a_local_cluster_add_up(client):
    binary = pathlib.Path(dask_precompute.default_sscc_binary())
    if not binary.exists():
        pytest.skip(f"no sscc binary at {binary} (built with SSCC_BUILD_VALIDATION)")
    whole = dask_precompute.kernel_range_task(str(binary), 3, 9, 20)
    assert dask_precompute.validate_kernels_on(client, 3, 9, ranges=4, per_seed=20, sscc_binary=str(binary)) == whole
    assert sum(values[0] for values in whole.values()) == 6 * 2 * (20 + 2)
    assert sum(values[2] for values in whole.values()) == 0
