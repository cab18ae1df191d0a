"""Runs the CommonRoad Scenario Designer's cr2odr on CommonRoad files, one process per map.

The peer side of `cargo bench -p osc2cr-road-export --bench peer`: for each input it writes
OUT_DIR/<stem>.xodr (if cr2odr gets that far) and prints one JSON line
{"file", "stem", "ok", "seconds", "error"}. Run it with the interpreter of a virtual
environment that holds only crdesigner (the bench makes one under target/peer).

    python peer_cr2odr.py OUT_DIR FILE.xml...
"""

import json
import multiprocessing as mp
import sys
import time
import traceback
from pathlib import Path

TIMEOUT = 600


def convert(path: str, out: str, queue) -> None:
    try:
        from crdesigner.map_conversion.map_conversion_interface import commonroad_to_opendrive

        start = time.perf_counter()
        commonroad_to_opendrive(Path(path), Path(out))
        queue.put({"ok": True, "seconds": time.perf_counter() - start, "error": None})
    except BaseException as e:  # noqa: BLE001 - a crash is the measurement
        last = traceback.extract_tb(e.__traceback__)[-1:] if e.__traceback__ else []
        where = f" ({last[0].filename.split('/')[-1]}:{last[0].lineno})" if last else ""
        queue.put({"ok": False, "seconds": None, "error": f"{type(e).__name__}: {e}{where}"})


def main() -> None:
    out_dir = Path(sys.argv[1])
    out_dir.mkdir(parents=True, exist_ok=True)
    for f in sys.argv[2:]:
        stem = Path(f).stem
        out = out_dir / f"{stem}.xodr"
        if out.exists():
            out.unlink()
        queue = mp.Queue()
        p = mp.Process(target=convert, args=(f, str(out), queue))
        p.start()
        p.join(TIMEOUT)
        if p.is_alive():
            p.kill()
            res = {"ok": False, "seconds": None, "error": f"timeout after {TIMEOUT} s"}
        else:
            res = queue.get() if not queue.empty() else {"ok": False, "seconds": None, "error": f"exit code {p.exitcode}"}
        if res["ok"] and not out.exists():
            res = {"ok": False, "seconds": res["seconds"], "error": "no file written"}
        print(json.dumps({"file": f, "stem": stem, **res}), flush=True)


if __name__ == "__main__":
    main()
