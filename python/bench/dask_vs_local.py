"""Times a 100,000-case sweep through Dask (a LocalCluster of 2 worker processes) against the local call.

    python python/bench/dask_vs_local.py [--cases 100000] [--workers 2] [--repeat 3]

Needs the dask extra (``pip install "./python[dask]"``). The grid: the rocking
block of the README's memory figure (0.5 m × 2 m, a 1 Hz sine pulse, 2 s per
case) over amplitudes × frequencies. The local call is ``rocking.sweep`` on
``--workers`` threads; the Dask call runs the same sweep cut into blocks on a
LocalCluster of ``--workers`` processes of one thread each, in the same
process's session (the cluster is started once, before the rounds, and its
start-up is reported apart). The two alternate in rounds, so that other load on
the machine falls on both; each round checks that the columns are identical.
Prints every round and the ratio of the medians (Dask / local).
"""

from __future__ import annotations

import argparse
import statistics
import time

import numpy as np
import rocking

BLOCK = {
    "name": "block",
    "tower": {"width": 0.5, "height": 2.0, "mass": 500.0},
    "ground": {"type": "sine-pulse", "amplitude": 0.5, "frequency": 1.0},
    "simulation": {"duration": 2.0},
}


def same(a, b) -> bool:
    """The same columns, equal values (NaN where NaN)."""
    if list(a) != list(b):
        return False
    for name in a:
        x, y = a[name], b[name]
        if x.dtype != y.dtype:
            return False
        if x.dtype == np.float64:
            if not np.array_equal(x, y, equal_nan=True):
                return False
        elif x.tolist() != y.tolist():
            return False
    return True


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--cases", type=int, default=100_000, help="cases (amplitudes × 1,000 frequencies)")
    parser.add_argument("--workers", type=int, default=2, help="threads of the local call, worker processes of the cluster")
    parser.add_argument("--repeat", type=int, default=3, help="rounds")
    args = parser.parse_args()
    from distributed import Client, LocalCluster

    amplitudes = max(1, args.cases // 1000)
    axes = {
        "ground.amplitude": {"from": 0.3, "to": 1.5, "steps": amplitudes},
        "ground.frequency": {"from": 0.5, "to": 5.0, "steps": 1000},
    }
    scenario = rocking.Scenario.from_dict(BLOCK)
    start = time.perf_counter()
    with LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, Client(cluster) as client:
        print(f"LocalCluster of {args.workers} processes started in {time.perf_counter() - start:.2f} s")
        local_times, dask_times = [], []
        for r in range(args.repeat):
            t = time.perf_counter()
            local = rocking.sweep(scenario, axes, threads=args.workers)
            local_times.append(time.perf_counter() - t)
            t = time.perf_counter()
            remote = rocking.sweep(scenario, axes, client=client)
            dask_times.append(time.perf_counter() - t)
            n = len(local["error"])
            print(
                f"round {r + 1}: {n} cases, local {local_times[-1]:.2f} s, dask {dask_times[-1]:.2f} s "
                f"({dask_times[-1] / local_times[-1]:.3f}×), identical: {same(local, remote)}"
            )
        lm, dm = statistics.median(local_times), statistics.median(dask_times)
        print(f"median: local {lm:.2f} s ({1e3 * lm / n:.3f} ms per case), dask {dm:.2f} s, dask / local {dm / lm:.3f}")


if __name__ == "__main__":
    main()
