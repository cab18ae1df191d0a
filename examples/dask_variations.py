"""Convert the variations of a parameter distribution with Dask, through the osc2cr Python API.

    pip install . dask distributed
    python examples/dask_variations.py ../shared/corpus/esmini/xosc/cut-in_parameter_set.xosc -o out/

Starts a dask.distributed LocalCluster (two worker processes by default), splits the
distribution's variations into chunks of consecutive indices, and has each worker convert
its chunks with ``osc2cr.variations(path, start=..., stop=...)`` — every variation is
computed from its index alone, so no worker needs another's work — and write
``OUT/<stem>_<index>.xml``: the names and bytes ``osc2cr convert DIST.xosc -o OUT`` writes.
With ``--format 2024`` each variation is ``OUT/<stem>_<index>-SC.pb`` and ``OUT/<stem>_<index>.pb``
and the map they share ``OUT/<map id>.pb``, as ``osc2cr convert --format 2024`` writes them.
Prints the throughput (variations per second) on stdout as JSON.

Point ``--scheduler`` at a running ``dask scheduler`` to use a real cluster instead (every
worker must see the input files and OUT at the same paths).
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile
import time
import warnings

import osc2cr


def convert_chunk(path: str, start: int, stop: int, out_dir: str, options: dict) -> list[int]:
    """Converts variations start <= index < stop of `path` into `out_dir`; returns their
    indices. Runs on a worker. Each file is written whole or not at all (temp + rename)."""
    warnings.simplefilter("ignore", osc2cr.ConversionWarning)
    done = []
    for v in osc2cr.variations(path, start=start, stop=stop, **options):
        if v.protobuf is not None:
            v.protobuf.write(out_dir, osc2cr.output_name(path, v.index, format="2024")[: -len("-SC.pb")])
            done.append(v.index)
            continue
        target = os.path.join(out_dir, osc2cr.output_name(path, v.index))
        fd, tmp = tempfile.mkstemp(dir=out_dir, prefix=".osc2cr-", suffix=".tmp")
        with os.fdopen(fd, "w", encoding="utf-8", newline="") as f:
            f.write(v.xml)
        os.replace(tmp, target)
        done.append(v.index)
    return done


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("distribution", help="a ParameterValueDistribution .xosc file")
    ap.add_argument("-o", "--output", required=True, help="output folder (created)")
    ap.add_argument("--workers", type=int, default=2, help="local worker processes (default 2)")
    ap.add_argument("--scheduler", help="address of a running Dask scheduler (no local cluster)")
    ap.add_argument("--chunk", type=int, default=0, help="variations per task (default: about 4 tasks per worker)")
    ap.add_argument("--max-variations", type=int, default=100, help="as the CLI's (default 100)")
    ap.add_argument("--dt", type=float, help="CommonRoad time step, s (the CLI's default if omitted)")
    ap.add_argument("--seed", type=int, help="seed of stochastic distributions")
    ap.add_argument("--format", choices=["2020a", "2024"], help="CommonRoad format (default 2020a)")
    args = ap.parse_args(argv)

    from dask.distributed import Client, LocalCluster

    path = os.path.abspath(args.distribution)
    out_dir = os.path.abspath(args.output)
    os.makedirs(out_dir, exist_ok=True)
    options = {"max_variations": args.max_variations, "dt": args.dt, "seed": args.seed, "format": args.format}
    options = {k: v for k, v in options.items() if v is not None}
    n = osc2cr.count_variations(path, **options)

    t0 = time.perf_counter()
    if args.scheduler:
        client = Client(args.scheduler)
        cluster = None
        workers = len(client.scheduler_info()["workers"]) or 1
    else:
        cluster = LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True,
                               dashboard_address=None)
        client = Client(cluster)
        workers = args.workers
    started = time.perf_counter()
    try:
        chunk = args.chunk or max(1, -(-n // (4 * workers)))
        futures = [
            client.submit(convert_chunk, path, a, min(a + chunk, n + 1), out_dir, options, pure=False)
            for a in range(1, n + 1, chunk)
        ]
        done = sorted(i for part in client.gather(futures) for i in part)
        finished = time.perf_counter()
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    if done != list(range(1, n + 1)):
        print(f"converted {len(done)} of {n} variations", file=sys.stderr)
        return 1
    seconds = finished - started
    print(json.dumps({
        "variations": n,
        "workers": workers,
        "chunk": chunk,
        "cluster_start_s": round(started - t0, 3),
        "convert_s": round(seconds, 3),
        "variations_per_s": round(n / seconds, 2) if seconds > 0 else None,
    }))
    return 0


if __name__ == "__main__":
    sys.exit(main())
