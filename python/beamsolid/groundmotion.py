"""Synthetic ground-motion records for examples and tests.

A record is white noise shaped in frequency by the Kanai-Tajimi filter
(the soil layer as a damped oscillator of frequency ``fg`` and damping
``zeta_g``), with the Clough-Penzien second filter (``fc``, ``zeta_c``)
removing the long-period drift that makes integrated displacements wander,
and modulated in time by the Jennings envelope (a quadratic rise to ``t1``,
strong motion to ``t2``, exponential decay with rate ``decay``). The record
is scaled to the peak ground acceleration ``pga``. Everything is
deterministic for a given ``seed`` (numpy's PCG64 generator).

Files are written the way OpenSees reads them: one value per line, so that
``timeSeries('Path', tag, '-dt', dt, '-filePath', path, '-factor', g)``
loads it; the time step and the parameters go to ``path + '.json'``.

    python -m beamsolid.groundmotion examples/records/synthetic_kt.acc --seed 16
"""
import argparse
import json

import numpy as np


def kanai_tajimi(duration=20.0, dt=0.01, pga=0.3, fg=2.5, zeta_g=0.6, fc=0.25, zeta_c=0.6,
                 t1=2.0, t2=8.0, decay=0.35, seed=16):
    """Ground acceleration (in units of g unless ``pga`` says otherwise) at
    times 0, dt, ..., as a numpy array. Frequencies in Hz."""
    if dt <= 0.0 or duration <= dt:
        raise ValueError("need dt > 0 and duration > dt")
    n = int(round(duration / dt)) + 1
    rng = np.random.default_rng(seed)
    noise = rng.standard_normal(n)
    # Filter in the frequency domain (zero padding keeps the filter causal-free of wrap-around).
    m = 2 * n
    w = 2.0 * np.pi * np.fft.rfftfreq(m, dt)
    wg, wc = 2.0 * np.pi * fg, 2.0 * np.pi * fc
    kt = (wg**2 + 2j * zeta_g * wg * w) / (wg**2 - w**2 + 2j * zeta_g * wg * w)
    cp = w**2 / (wc**2 - w**2 + 2j * zeta_c * wc * w)
    acc = np.fft.irfft(np.fft.rfft(noise, m) * kt * cp, m)[:n]
    t = np.arange(n) * dt
    envelope = np.where(t < t1, (t / t1) ** 2, np.where(t <= t2, 1.0, np.exp(-decay * (t - t2))))
    # A half-cosine taper over the last second ends the record at exactly 0.
    taper = np.clip((t[-1] - t) / min(1.0, t[-1]), 0.0, 1.0)
    window = envelope * np.where(taper < 1.0, 0.5 - 0.5 * np.cos(np.pi * taper), 1.0)
    acc *= window
    # Baseline correction: subtract window * (c0 + c1 t/T) so that the ground
    # ends at rest where it started (final velocity and displacement 0 under
    # the trapezoidal rule the analysis uses).
    basis = np.stack([window, window * t / t[-1]])
    acc -= np.linalg.solve(np.array([[_velocity_end(b, dt), _displacement_end(b, dt)] for b in basis]).T,
                           [_velocity_end(acc, dt), _displacement_end(acc, dt)]) @ basis
    return pga * acc / np.max(np.abs(acc))


def integrate(values, dt):
    """Running trapezoidal integral from 0 (velocity from acceleration, ...)."""
    out = np.zeros_like(values, dtype=float)
    out[1:] = np.cumsum(0.5 * dt * (values[1:] + values[:-1]))
    return out


def _velocity_end(acc, dt):
    return integrate(acc, dt)[-1]


def _displacement_end(acc, dt):
    return integrate(integrate(acc, dt), dt)[-1]


def write_record(path, acc, dt, **meta):
    """One value per line at ``path``; dt and metadata in ``path + '.json'``."""
    with open(path, "w") as f:
        for a in acc:
            f.write(f"{a:.10e}\n")
    info = {"dt": dt, "npts": len(acc), "units": "g", "format": "one value per line", **meta}
    with open(path + ".json", "w") as f:
        json.dump(info, f, indent=1)


def read_record(path):
    """(dt, accelerations) of a record written by write_record."""
    with open(path + ".json") as f:
        dt = json.load(f)["dt"]
    return dt, np.loadtxt(path)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("path")
    parser.add_argument("--duration", type=float, default=20.0)
    parser.add_argument("--dt", type=float, default=0.01)
    parser.add_argument("--pga", type=float, default=0.3)
    parser.add_argument("--fg", type=float, default=2.5)
    parser.add_argument("--zeta-g", type=float, default=0.6)
    parser.add_argument("--seed", type=int, default=16)
    a = parser.parse_args(argv)
    acc = kanai_tajimi(duration=a.duration, dt=a.dt, pga=a.pga, fg=a.fg, zeta_g=a.zeta_g, seed=a.seed)
    write_record(a.path, acc, a.dt, generator="beamsolid.groundmotion.kanai_tajimi", seed=a.seed, pga=a.pga,
                 fg=a.fg, zeta_g=a.zeta_g, duration=a.duration)


if __name__ == "__main__":
    main()
