"""Parameter sweeps on Dask: one function of a model's parameters, run over a grid or a list of points.

Every run of a sweep is an independent ``beamsolid.Model``, so the runs go to Dask
(``dask[distributed]``) instead of a loop: a local cluster of worker processes by default
(one per core, one thread each, one BLAS thread each), or an existing scheduler given by its
address. Results go to a folder of Parquet files (PyArrow), one file per finished point, keyed
by the point's parameters and written by the client as each run finishes, so that

- a re-run skips the points already stored (``retry_failed`` re-runs the failed ones),
- an interrupted sweep loses nothing that finished,
- a point that raises, or whose analysis fails, is stored with its error text and the
  ``analyze`` return code (status ``error`` or ``failed``) and the other points go on.

The function takes the parameters as keyword arguments and returns a dict of results
(numbers, strings, None; lists and dicts are stored as JSON text and decoded by ``read``)::

    from beamsolid import sweep

    def tip(P, L):
        m = beamsolid.Model()
        ...                                  # build the model
        sweep.analyze(m, 10)                 # analyze(10); raises AnalyzeFailed on a negative code
        return {"u": m.nodeDisp(2, 1)}

    sweep.run(tip, sweep.grid(P=[1.0, 2.0], L=[3.0, 4.0]), "out/tip")
    rows = sweep.read("out/tip")             # one dict per point: parameters, status, results

A function may also return ``returncode`` (and ``error``) among its results: a negative code
marks the point failed while keeping its other results. From the shell::

    python -m beamsolid.sweep run my_study.py:tip out/tip --grid P=1,2 --grid L=3,4 [--scheduler ADDRESS]
    python -m beamsolid.sweep show out/tip

docs/sweeps.md has the details and the setup on several machines.
"""
import argparse
import contextlib
import dataclasses
import datetime
import hashlib
import importlib
import itertools
import json
import math
import os
import pathlib
import socket
import sys
import time
import traceback
import warnings

__all__ = ["AnalyzeFailed", "Summary", "analyze", "grid", "read", "read_table", "run", "main"]

# Columns every part file has besides the parameters and the function's results.
STATUS_COLUMNS = ("status", "returncode", "error", "wall", "worker", "finished")
KEY = "point_key"
RESERVED = (KEY,) + STATUS_COLUMNS
JSON_COLUMNS = b"beamsolid.sweep.json_columns"  # part-file metadata: columns stored as JSON text
# Set in each worker process before it starts (before it imports numpy or beamsolid): one BLAS
# thread per worker, since the workers already fill the cores.
WORKER_ENV = {"OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1", "MKL_NUM_THREADS": "1"}
ERROR_CHARS = 4000  # the tail of a traceback is where the reason is


class AnalyzeFailed(RuntimeError):
    """An analysis returned a negative code: the point is stored as failed, with the code."""

    def __init__(self, returncode, message="", results=None):
        super().__init__(f"analyze returned {returncode}" + (f": {message}" if message else ""))
        self.returncode = int(returncode)
        self.results = dict(results or {})


def analyze(m, *args):
    """``m.analyze(*args)``, raising AnalyzeFailed (with ``m.last_error()``) on a negative code."""
    code = m.analyze(*args)
    if code < 0:
        raise AnalyzeFailed(code, m.last_error())
    return code


def grid(**axes):
    """The points of the Cartesian product of the axes, the last axis varying fastest."""
    names = list(axes)
    return [dict(zip(names, values)) for values in itertools.product(*(list(axes[n]) for n in names))]


def _scalar(value):
    return value is None or isinstance(value, (bool, int, float, str))


def point_key(params):
    """The point's key: its parameters as canonical JSON (names sorted, floats exact)."""
    for name, value in params.items():
        if not isinstance(name, str) or name in RESERVED:
            raise ValueError(f"sweep: parameter name {name!r} is not allowed (reserved: {', '.join(RESERVED)})")
        if not _scalar(value) or (isinstance(value, float) and not math.isfinite(value)):
            raise ValueError(f"sweep: parameter {name} = {value!r}: parameters must be finite numbers, "
                             "strings, booleans or None")
    return json.dumps(params, sort_keys=True, separators=(",", ":"))


def _part_name(key):
    return "point-" + hashlib.sha1(key.encode()).hexdigest()[:20] + ".parquet"


# --- the worker side: one point ---------------------------------------------------------------------
def _call(func, params):
    """Run func(**params) and return what goes into the point's row (never raises). func may come
    as cloudpickle bytes (what run() sends to Dask workers)."""
    t0 = time.perf_counter()
    row = dict(status="ok", returncode=0, error=None)
    results = {}
    try:
        if isinstance(func, bytes):
            import cloudpickle

            func = cloudpickle.loads(func)
        out = func(**params)
        if out is None:
            out = {}
        if not isinstance(out, dict):
            raise TypeError(f"the sweep function returned {type(out).__name__}, not a dict of results")
        results = dict(out)
        if "returncode" in results:
            code = results.pop("returncode")
            row["returncode"] = None if code is None else int(code)
            if code is not None and code < 0:
                row["status"] = "failed"
        if "error" in results:
            row["error"] = results.pop("error")
            if row["error"] and row["status"] == "ok":
                row["status"] = "failed"
    except AnalyzeFailed as exc:
        row.update(status="failed", returncode=exc.returncode, error=str(exc))
        results = exc.results
    except (Exception, SystemExit) as exc:  # a point that raises is stored with the reason; the sweep goes on
        row.update(status="error", returncode=getattr(exc, "returncode", None),
                   error=f"{type(exc).__name__}: {exc}\n{traceback.format_exc()[-ERROR_CHARS:]}")
        results = {}
    clash = sorted(set(results) & (set(params) | set(RESERVED)))
    if clash:
        row.update(status="error", error=f"ValueError: result names {clash} repeat a parameter or a status column")
        results = {}
    row["wall"] = time.perf_counter() - t0
    row["worker"] = f"{socket.gethostname()}:{os.getpid()}"
    return row, results


def _worker_blas():
    """BLAS threads of a worker (checked once per sweep: a worker started by hand may have more)."""
    import beamsolid

    return dict(threads=int(beamsolid.blas_info().threads), env=os.environ.get("OPENBLAS_NUM_THREADS"))


# --- the store -----------------------------------------------------------------------------------------
def _write_part(store, params, key, row, results):
    import pyarrow as pa
    import pyarrow.parquet as pq

    record = {**params, KEY: key, **row, "finished": datetime.datetime.now(datetime.timezone.utc).isoformat()}
    json_columns = []
    for name, value in results.items():
        if _scalar(value):
            record[name] = value
        elif hasattr(value, "item") and getattr(value, "ndim", 1) == 0:  # a numpy scalar
            record[name] = value.item()
        else:  # lists, dicts: JSON text, decoded again by read()
            record[name] = json.dumps(value, default=_plain)
            json_columns.append(name)
    table = pa.Table.from_pylist([record])
    table = table.replace_schema_metadata({JSON_COLUMNS: json.dumps(json_columns).encode()})
    path = store / _part_name(key)
    tmp = path.with_suffix(f".{os.getpid()}.tmp")
    pq.write_table(table, tmp)
    os.replace(tmp, path)  # a killed sweep leaves a whole part or none


def _plain(value):
    """JSON for what json cannot take: numpy scalars and arrays, tuples inside dataclasses."""
    if hasattr(value, "tolist"):
        return value.tolist()
    if dataclasses.is_dataclass(value):
        return dataclasses.asdict(value)
    return str(value)


def _parts(store):
    return sorted(pathlib.Path(store).glob("point-*.parquet"))


def _stored(store):
    """{key: status} of the points in the store."""
    import pyarrow.parquet as pq

    done = {}
    for path in _parts(store):
        table = pq.read_table(path, columns=[KEY, "status"])
        for key, status in zip(table.column(KEY).to_pylist(), table.column("status").to_pylist()):
            done[key] = status
    return done


def read_table(store):
    """The store as one pyarrow Table (JSON columns left as text); None if it holds no point."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    tables = [pq.read_table(p) for p in _parts(store)]
    if not tables:
        return None
    return pa.concat_tables([t.replace_schema_metadata(None) for t in tables], promote_options="permissive")


def read(store, points=None):
    """One dict per stored point (parameters, status columns, results; JSON columns decoded),
    in the order of their keys; with `points`, one per point in that order (None if not stored)."""
    import pyarrow.parquet as pq

    rows = []
    for path in _parts(store):
        table = pq.read_table(path)
        meta = table.schema.metadata or {}
        json_columns = json.loads(meta.get(JSON_COLUMNS, b"[]"))
        for row in table.to_pylist():
            for name in json_columns:
                if row.get(name) is not None:
                    row[name] = json.loads(row[name])
            rows.append(row)
    if points is not None:
        by_key = {r[KEY]: r for r in rows}
        return [by_key.get(point_key(dict(p))) for p in points]
    return sorted(rows, key=lambda r: r[KEY])


# --- progress ------------------------------------------------------------------------------------------
def _clock(seconds):
    seconds = int(round(seconds))
    return f"{seconds // 3600}:{seconds // 60 % 60:02d}:{seconds % 60:02d}"


class _Progress:
    """Points done, failed, time left, on stderr (at most every `every` seconds, and at the end)."""

    def __init__(self, name, todo, skipped, show, every=2.0):
        self.name, self.todo, self.skipped, self.every = name, todo, skipped, every
        self.show = show
        self.done = self.failed = self.errors = 0
        self.t0 = self.last = time.perf_counter()
        self.shown = None

    def start(self):
        """The clock of the time left starts when the points are sent (not while workers start)."""
        self.t0 = time.perf_counter()

    def line(self):
        elapsed = time.perf_counter() - self.t0
        left = elapsed / self.done * (self.todo - self.done) if self.done else float("nan")
        return (f"sweep {self.name}: {self.done}/{self.todo} done, {self.failed + self.errors} failed "
                f"({self.failed} analyze, {self.errors} raised)"
                + (f" ({self.skipped} already stored)" if self.skipped else "")
                + f", {_clock(elapsed)} elapsed, " + (f"~{_clock(left)} left" if self.done else "time left unknown"))

    def update(self, status, final=False):
        if status is not None:
            self.done += 1
            self.failed += status == "failed"
            self.errors += status == "error"
        now = time.perf_counter()
        if not self.show or not (final or now - self.last >= self.every or self.done == self.todo):
            return
        if self.shown == (self.done, self.todo) and not status and self.done == self.todo:
            return  # the end was shown already
        self.shown = (self.done, self.todo)
        self.last = now
        if callable(self.show):
            self.show(self)
        else:
            print(self.line(), file=sys.stderr, flush=True)


@dataclasses.dataclass
class Summary:
    """What one call of run() did."""

    store: str
    points: int  # in the sweep
    skipped: int  # already stored, not run again
    ran: int  # run now (ok + failed + errors)
    ok: int
    failed: int  # status "failed": an analysis returned a negative code
    errors: int  # status "error": the function raised (or its worker died)
    wall: float  # seconds
    workers: int  # Dask workers (0: serial)


# --- the sweep -----------------------------------------------------------------------------------------
@contextlib.contextmanager
def _client(scheduler, workers):
    """A Dask client: on the scheduler at `scheduler`, or on a local cluster of worker processes."""
    import dask
    from distributed import Client, LocalCluster

    if scheduler:
        with Client(scheduler) as client:
            yield client
        return
    workers = workers or os.cpu_count() or 1
    # Dask sets pre-spawn-environ in this process's environment before it spawns each worker
    # (the worker then starts with it; a restarted worker gets it again); put this process's own
    # environment back afterwards.
    saved = dict(os.environ)
    environ = {**dask.config.get("distributed.nanny.pre-spawn-environ", {}), **WORKER_ENV}
    try:
        with dask.config.set({"distributed.nanny.pre-spawn-environ": environ}):
            cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                   dashboard_address=None, worker_dashboard_address=None)
    finally:
        os.environ.clear()
        os.environ.update(saved)
    with cluster, Client(cluster) as client:
        yield client


def run(func, points, store, *, scheduler=None, workers=None, serial=False, retry_failed=False, progress=True,
        name=None):
    """Run func(**point) for every point not yet in `store` (a folder, made if missing); return a Summary.

    scheduler: a Dask scheduler address ("tcp://host:8786"); otherwise a local cluster of `workers`
    worker processes (default: one per core). serial=True runs the points here, one after the other,
    into the same store (the loop without Dask). retry_failed: run the points stored as failed or
    error again. progress: False, True (lines on stderr) or a callable taking the progress object.
    """
    points = [dict(p) for p in points]
    keys = [point_key(p) for p in points]
    seen = set()
    for key in keys:
        if key in seen:
            raise ValueError(f"sweep: the point {key} appears twice")
        seen.add(key)
    store = pathlib.Path(store)
    store.mkdir(parents=True, exist_ok=True)
    for tmp in store.glob("point-*.tmp"):
        tmp.unlink()  # a part a killed sweep was writing
    stored = _stored(store)
    todo = [(p, k) for p, k in zip(points, keys)
            if k not in stored or (retry_failed and stored[k] != "ok")]
    name = name or getattr(func, "__name__", "sweep")
    bar = _Progress(name, len(todo), len(points) - len(todo), progress)
    counts = {"ok": 0, "failed": 0, "error": 0}
    t0 = time.perf_counter()
    n_workers = 0

    def finish(params, key, row, results):
        _write_part(store, params, key, row, results)
        counts[row["status"]] += 1
        bar.update(row["status"])

    if todo and serial:
        bar.start()
        bar.update(None, final=True)
        for params, key in todo:
            finish(params, key, *_call(func, params))
    elif todo:
        from distributed import as_completed

        with _client(scheduler, workers) as client:
            n_workers = len(client.scheduler_info().get("workers", {}))
            blas = client.run(_worker_blas)
            many = sorted(w for w, b in blas.items() if b["threads"] > 1)
            if many:
                warnings.warn(f"sweep: workers {many} run more than one BLAS thread each; start them with "
                              "OPENBLAS_NUM_THREADS=1 (docs/sweeps.md)", RuntimeWarning, stacklevel=2)
            bar.start()
            bar.update(None, final=True)
            # Dask pickles a task by reference where it can; cloudpickle here honours
            # register_pickle_by_value (a study file the workers do not have), once for all points.
            import cloudpickle

            payload = cloudpickle.dumps(func)
            futures = {}
            for params, key in todo:
                future = client.submit(_call, payload, params, pure=False,
                                       key=f"{name}-{hashlib.sha1(key.encode()).hexdigest()[:20]}")
                futures[future] = (params, key)
            lost = []
            try:
                for future in as_completed(futures):
                    params, key = futures.pop(future)
                    try:
                        row, results = future.result()
                    except Exception:  # the worker died under it (a crash), or the task was lost
                        lost.append((params, key))
                        continue
                    finish(params, key, row, results)
                # Dask blames every task a dying worker held, so a point that only shared a worker
                # with a crashing one can be lost too (seen: 2 of 6 lost for 1 crash). Each lost
                # point runs again on its own: an innocent one completes, a crashing one is stored
                # as an error.
                for params, key in lost:
                    future = client.submit(_call, payload, params, pure=False,
                                           key=f"{name}-alone-{hashlib.sha1(key.encode()).hexdigest()[:20]}")
                    futures[future] = (params, key)
                    try:
                        row, results = future.result()
                    except Exception as exc:
                        row = dict(status="error", returncode=None, wall=None, worker=None,
                                   error=f"{type(exc).__name__}: {exc} (the worker running the point stopped)")
                        results = {}
                    futures.pop(future)
                    finish(params, key, row, results)
            finally:
                client.cancel(list(futures))
    bar.update(None, final=True)
    return Summary(store=str(store), points=len(points), skipped=len(points) - len(todo),
                   ran=sum(counts.values()), ok=counts["ok"], failed=counts["failed"], errors=counts["error"],
                   wall=time.perf_counter() - t0, workers=n_workers)


# --- the command line ----------------------------------------------------------------------------------
def _value(text):
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return {"true": True, "false": False, "none": None}.get(text.lower(), text)


def load_function(spec):
    """'package.module:function' or 'path/to/file.py:function'. A file's module is sent to the workers
    by value (they need not have the file); what it imports, they must have."""
    target, sep, attr = spec.rpartition(":")
    if not sep or not target or not attr:
        raise SystemExit(f"sweep: FUNCTION must be module:function or file.py:function, not {spec!r}")
    if target.endswith(".py"):
        path = pathlib.Path(target).resolve()
        if not path.is_file():
            raise SystemExit(f"sweep: no file {target}")
        sys.path.insert(0, str(path.parent))
        module = importlib.import_module(path.stem)
        import cloudpickle

        cloudpickle.register_pickle_by_value(module)
    else:
        module = importlib.import_module(target)
    try:
        return getattr(module, attr)
    except AttributeError:
        raise SystemExit(f"sweep: {target} has no function {attr}") from None


def _points(args):
    points = []
    if args.points:
        text = pathlib.Path(args.points).read_text()
        points = json.loads(text) if text.lstrip().startswith("[") else [json.loads(l) for l in text.splitlines()
                                                                         if l.strip()]
    axes = {}
    for item in args.grid or []:
        axis, sep, values = item.partition("=")
        if not sep or not axis or not values:
            raise SystemExit(f"sweep: --grid takes NAME=V1,V2,..., not {item!r}")
        axes[axis] = [_value(v) for v in values.split(",")]
    if axes:
        points = [{**p, **g} for p in (points or [{}]) for g in grid(**axes)]
    if not points:
        raise SystemExit("sweep: no points (give --grid NAME=V1,V2,... or --points FILE)")
    return points


def _show(store, failed_only):
    rows = read(store)
    if not rows:
        print(f"{store}: no points stored")
        return 0
    count = {s: sum(r["status"] == s for r in rows) for s in ("ok", "failed", "error")}
    print(f"{store}: {len(rows)} points: {count['ok']} ok, {count['failed']} failed, {count['error']} error")
    status_like = set(RESERVED)
    for r in rows:
        if failed_only and r["status"] == "ok":
            continue
        params = json.loads(r[KEY])
        results = {k: v for k, v in r.items() if k not in status_like and k not in params}
        text = " ".join(f"{k}={v}" for k, v in params.items())
        text += f"  {r['status']}"
        if r["status"] != "ok":
            text += f" (code {r['returncode']}): {(r['error'] or '').splitlines()[0] if r['error'] else ''}"
        else:
            text += "  " + " ".join(f"{k}={v:.6g}" if isinstance(v, float) else f"{k}={v}"
                                    for k, v in results.items() if _scalar(v))
        print(text)
    return 0


def main(argv=None):
    ap = argparse.ArgumentParser(prog="python -m beamsolid.sweep", description=__doc__.split("\n\n")[0])
    sub = ap.add_subparsers(dest="command", required=True)
    r = sub.add_parser("run", help="run a function over a grid or a list of points")
    r.add_argument("function", help="module:function or file.py:function")
    r.add_argument("store", help="the results folder (Parquet parts; made if missing)")
    r.add_argument("--grid", action="append", metavar="NAME=V1,V2,...", help="one axis of the grid (repeat)")
    r.add_argument("--points", metavar="FILE", help="a JSON list (or JSON lines) of parameter dicts")
    r.add_argument("--scheduler", metavar="ADDRESS", help="an existing Dask scheduler (tcp://host:8786)")
    r.add_argument("--workers", type=int, help="local worker processes (default: one per core)")
    r.add_argument("--serial", action="store_true", help="run the points here, one after the other")
    r.add_argument("--retry-failed", action="store_true", help="run the points stored as failed again")
    r.add_argument("--quiet", action="store_true", help="no progress lines")
    s = sub.add_parser("show", help="list the points in a results folder")
    s.add_argument("store")
    s.add_argument("--failed", action="store_true", help="only the points that failed")
    args = ap.parse_args(argv)
    if args.command == "show":
        return _show(args.store, args.failed)
    func = load_function(args.function)
    summary = run(func, _points(args), args.store, scheduler=args.scheduler, workers=args.workers,
                  serial=args.serial, retry_failed=args.retry_failed, progress=not args.quiet)
    print(f"sweep: {summary.points} points, {summary.skipped} already stored, {summary.ran} run: {summary.ok} ok, "
          f"{summary.failed} failed, {summary.errors} error ({summary.wall:.1f} s, "
          f"{summary.workers or 'no'} Dask workers); results in {summary.store}")
    return 0


if __name__ == "__main__":
    # Run as `python -m beamsolid.sweep`: use the importable module, so that what the workers
    # unpickle is beamsolid.sweep, not this __main__.
    from beamsolid.sweep import main as _main

    sys.exit(_main())
