"""beamsolid.sweep (issue 19): parameter sweeps on Dask with a Parquet store.

The point function is tests/python/sweep_points.bar: an elastic-perfectly-plastic bar
pulled by P, whose end moves P L / (E A) below the yield force N_y = 20 and whose
analysis fails above it. Checked: two local workers give the serial loop's results
bit for bit, and the closed form to 1e-12; a point that raises (unknown material) or
fails to converge is stored with its error and return code while the others complete;
a sweep killed halfway (SIGKILL of the client process) keeps every finished point and
its re-run runs exactly the missing ones; no worker process outlives a sweep.
"""
import os
import pathlib
import signal
import subprocess
import sys
import time

import psutil
import pytest

from beamsolid import sweep

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parents[1]
sys.path.insert(0, str(HERE))
import sweep_points as sp  # noqa: E402

VOLATILE = ("wall", "worker", "finished")  # differ between runs by nature


def _stable(row):
    out = {k: v for k, v in row.items() if k not in VOLATILE}
    # An unknown type's message lists the registered types, and this process may hold
    # more (plugins an earlier test loaded) than a fresh worker: compare up to the list.
    if out.get("error"):
        out["error"] = out["error"].split(" (known:")[0]
    return out


def same_point(a, b):
    return _stable(a) == _stable(b)


def alive(p):
    try:
        return p.is_running() and p.status() != psutil.STATUS_ZOMBIE
    except psutil.NoSuchProcess:
        return False


@pytest.fixture
def no_leftover_processes():
    before = {p.pid for p in psutil.Process().children(recursive=True)}
    yield
    deadline = time.time() + 20
    while True:
        left = [p for p in psutil.Process().children(recursive=True) if p.pid not in before and alive(p)
                and "resource_tracker" not in " ".join(p.cmdline())]  # multiprocessing's one helper
        if not left or time.time() > deadline:
            break
        time.sleep(0.2)
    assert not left, f"processes left behind: {[(p.pid, p.cmdline()) for p in left]}"


POINTS = sweep.grid(P=[4.0, 12.5, 19.0, 30.0], L=[1.0, 3.5], material=["ElasticPP", "NoSuchMaterial"])


def check_bar_rows(rows):
    """The closed form for the converged points, the failure for the others."""
    for p, r in zip(POINTS, rows):
        assert r is not None, f"point {p} not stored"
        if p["material"] == "NoSuchMaterial":
            assert r["status"] == "error" and r["returncode"] is None
            assert "OpenSeesError" in r["error"] and "uniaxialMaterial" in r["error"] and "NoSuchMaterial" in r["error"]
        elif p["P"] > sp.E * sp.AREA * sp.EPS_Y:
            assert r["status"] == "failed" and r["returncode"] < 0
            assert f"analyze returned {r['returncode']}" in r["error"]
            assert "u" not in r or r["u"] is None
        else:
            assert r["status"] == "ok" and r["returncode"] == 0 and r["error"] is None
            u = p["P"] * p["L"] / (sp.E * sp.AREA)
            assert abs(r["u"] - u) <= 1e-12 * u
            assert abs(r["N"] - p["P"]) <= 1e-12 * p["P"]
            assert r["history"] == [r["u"], 1.0]  # a list result comes back as a list


def test_two_workers_match_the_serial_loop_point_by_point(tmp_path, no_leftover_processes):
    environ = dict(os.environ)
    serial = sweep.run(sp.bar, POINTS, tmp_path / "serial", serial=True, progress=False)
    dask = sweep.run(sp.bar, POINTS, tmp_path / "dask", workers=2, progress=False)
    assert os.environ == environ  # the workers' BLAS settings did not leak into this process
    for s in (serial, dask):
        assert (s.points, s.ran, s.skipped, s.ok, s.failed, s.errors) == (16, 16, 0, 6, 2, 8)
    assert dask.workers == 2 and serial.workers == 0
    a, b = sweep.read(tmp_path / "serial", POINTS), sweep.read(tmp_path / "dask", POINTS)
    check_bar_rows(a)
    check_bar_rows(b)
    for p, ra, rb in zip(POINTS, a, b):
        assert same_point(ra, rb), f"{p}: serial {ra} != dask {rb}"
    assert len({r["worker"] for r in b}) == 2  # both workers ran points
    table = sweep.read_table(tmp_path / "dask")  # the parts read back as one table
    assert table.num_rows == 16 and {"P", "L", "material", "status", "returncode", "error", "u"} <= set(
        table.column_names)


def test_a_returned_negative_code_marks_the_point_failed_and_keeps_its_results(tmp_path):
    points = sweep.grid(P=[10.0, 30.0], L=[2.0])
    s = sweep.run(sp.bar_code, points, tmp_path, serial=True, progress=False)
    assert (s.ok, s.failed, s.errors) == (1, 1, 0)
    ok, failed = sweep.read(tmp_path, points)
    assert ok["status"] == "ok" and abs(ok["u"] - 10.0 * 2.0 / (sp.E * sp.AREA)) <= 1e-12 * ok["u"]
    # P = 30 > N_y = 20: steps of 7.5, the third (22.5) fails; the bar stays at time 0.5, P = 15.
    assert failed["status"] == "failed" and failed["returncode"] < 0 and "singular" in failed["error"]
    assert failed["time"] == 0.5 and abs(failed["u"] - 15.0 * 2.0 / (sp.E * sp.AREA)) <= 1e-12 * failed["u"]
    # A re-run skips both; retry_failed runs the failed one again (and only it).
    assert sweep.run(sp.bar_code, points, tmp_path, serial=True, progress=False).ran == 0
    again = sweep.run(sp.bar_code, points, tmp_path, serial=True, retry_failed=True, progress=False)
    assert (again.skipped, again.ran, again.failed) == (1, 1, 1)


def test_workers_run_one_blas_thread_each(tmp_path, no_leftover_processes):
    points = sweep.grid(i=[0, 1, 2, 3])
    sweep.run(sp.blas, points, tmp_path, workers=2, progress=False)
    rows = sweep.read(tmp_path, points)
    assert all(r["status"] == "ok" for r in rows)
    assert {r["env"] for r in rows} == {"1"}
    assert {r["threads"] for r in rows} <= {1, 0}  # 0: no OpenBLAS loaded at all
    assert os.getpid() not in {r["pid"] for r in rows}


def test_an_existing_scheduler_is_used_when_given(tmp_path, no_leftover_processes):
    from distributed import Client, LocalCluster

    points = sweep.grid(P=[5.0, 25.0], L=[1.0])
    with LocalCluster(n_workers=1, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with Client(cluster) as client:
            worker_pids = set(client.run(os.getpid).values())
        s = sweep.run(sp.bar, points, tmp_path, scheduler=cluster.scheduler_address, progress=False)
    assert (s.workers, s.ok, s.failed) == (1, 1, 1)
    rows = sweep.read(tmp_path, points)
    assert {int(r["worker"].rsplit(":", 1)[1]) for r in rows} == worker_pids
    assert os.getpid() not in worker_pids


def group_members(pgid):
    members = []
    for p in psutil.process_iter(["pid"]):
        try:
            if os.getpgid(p.pid) == pgid and p.status() != psutil.STATUS_ZOMBIE:
                members.append(p.pid)
        except (ProcessLookupError, psutil.NoSuchProcess):
            pass
    return members


def test_a_sweep_killed_halfway_keeps_what_finished_and_the_rerun_runs_only_the_rest(tmp_path):
    store = tmp_path / "killed"
    n = 12
    cmd = [sys.executable, "-m", "beamsolid.sweep", "run", f"{HERE / 'sweep_points.py'}:bar", str(store),
           "--workers", "2", "--grid", "P=" + ",".join(str(float(i)) for i in range(1, n + 1)), "--grid", "L=2.0",
           "--grid", "pause=0.4", "--quiet"]
    env = dict(os.environ, PYTHONPATH=str(ROOT / "python"))
    proc = subprocess.Popen(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, start_new_session=True)
    try:
        deadline = time.time() + 60
        while len(list(store.glob("point-*.parquet"))) < 4:
            assert proc.poll() is None, proc.communicate()
            assert time.time() < deadline, "the sweep stored no 4 points in 60 s"
            time.sleep(0.05)
        proc.kill()  # SIGKILL of the client: no chance to clean up
        proc.wait()
        # Its worker processes stop by themselves once their parent is gone.
        deadline = time.time() + 30
        while group_members(proc.pid) and time.time() < deadline:
            time.sleep(0.2)
        assert not group_members(proc.pid), "worker processes outlived the killed sweep"
    finally:
        if group_members(proc.pid):
            os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
    parts = {p.name: p.read_bytes() for p in store.glob("point-*.parquet")}
    kept = len(parts)
    assert 4 <= kept < n, f"{kept} of {n} points stored before the kill"
    points = sweep.grid(P=[float(i) for i in range(1, n + 1)], L=[2.0], pause=[0.4])
    s = sweep.run(sp.bar, points, store, serial=True, progress=False)
    assert (s.skipped, s.ran) == (kept, n - kept)
    assert {p.name: p.read_bytes() for p in store.glob("point-*.parquet") if p.name in parts} == parts
    assert not list(store.glob("*.tmp"))
    rows = sweep.read(store, points)
    for p, r in zip(points, rows):
        assert r["status"] == ("ok" if p["P"] <= 20.0 else "failed")
        if r["status"] == "ok":
            assert abs(r["u"] - p["P"] * 2.0 / (sp.E * sp.AREA)) <= 1e-12 * r["u"]


def test_bad_points_are_refused_before_anything_runs(tmp_path):
    with pytest.raises(ValueError, match="appears twice"):
        sweep.run(sp.bar, [dict(P=1.0, L=1.0), dict(L=1.0, P=1.0)], tmp_path, serial=True)
    with pytest.raises(ValueError, match="parameter P"):
        sweep.run(sp.bar, [dict(P=[1.0], L=1.0)], tmp_path, serial=True)
    with pytest.raises(ValueError, match="status"):
        sweep.run(sp.bar, [dict(status=1.0)], tmp_path, serial=True)
    assert sweep.read(tmp_path) == []


def test_command_line_show_lists_the_points(tmp_path):
    points = sweep.grid(P=[5.0, 25.0], L=[1.0])
    sweep.run(sp.bar, points, tmp_path, serial=True, progress=False)
    out = subprocess.run([sys.executable, "-m", "beamsolid.sweep", "show", str(tmp_path)], capture_output=True,
                         text=True, env=dict(os.environ, PYTHONPATH=str(ROOT / "python")), check=True).stdout
    assert "2 points: 1 ok, 1 failed, 0 error" in out
    assert "u=0.0025" in out and "failed (code -3)" in out


def test_a_point_that_kills_its_worker_is_stored_as_an_error_and_the_others_complete(tmp_path,
                                                                                    no_leftover_processes):
    points = sweep.grid(i=[0, 1, 2, 3, 4, 5])
    s = sweep.run(sp.crash, points, tmp_path, workers=2, progress=False)
    assert (s.ran, s.ok, s.errors) == (6, 5, 1)
    rows = sweep.read(tmp_path, points)
    for p, r in zip(points, rows):
        if p["i"] == 2:
            assert r["status"] == "error" and "KilledWorker" in r["error"]
        else:
            assert r["status"] == "ok" and r["square"] == p["i"] ** 2
