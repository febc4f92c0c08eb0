"""Adaptive static stepping: cut the step on failure, grow it back after easy steps.

``adaptive_analyze`` advances a static analysis along a scalar *progress* (the pseudo time of
a ``LoadControl`` analysis, the controlled displacement of a ``DisplacementControl`` one) from
0 to ``total`` in nominal steps of ``total / steps``. Before every step it re-issues the
integrator with the step's increment (only when the increment changes), so it works with any
integrator whose increment is one number::

    adaptive_analyze(m, total=1.0, steps=20)                                   # LoadControl
    adaptive_analyze(m, total=0.05, steps=10,
                     integrator=lambda d: ("DisplacementControl", head, 1, d))

A failed ``analyze(1)`` leaves the model at its last converged state (beamsolid's static
analysis reverts the domain and the integrator), so a failed step is simply retried with half
the increment, down to ``total / steps * min_fraction``; after ``grow_after`` consecutive
converged steps that took at most ``easy_iterations`` iterations the increment doubles again,
up to the nominal one. ``breakpoints`` (progress values such as the peaks of a cyclic
protocol) are hit exactly: a step never crosses one. With ``adaptive=False`` the first failure
ends the run (plain fixed stepping through the same code path).
"""
from dataclasses import dataclass, field

__all__ = ["StepperResult", "adaptive_analyze"]


@dataclass
class StepperResult:
    """What ``adaptive_analyze`` did."""

    converged: bool = False  # reached `total`
    progress: float = 0.0  # progress of the last converged state
    steps: int = 0  # converged steps
    failures: int = 0  # failed analyze(1) calls (each one is followed by a cut, or ends the run)
    cuts: int = 0  # increments halved
    grows: int = 0  # increments doubled
    iterations: list = field(default_factory=list)  # per converged step
    increments: list = field(default_factory=list)  # per converged step
    failed_at: float = None  # progress of the state the run stopped in (None if converged)
    returncode: int = 0  # the code of the analyze(1) that ended a failed run
    error: str = ""  # and its reason (the model's last_error(), when it has one)


def _default_integrator(d):
    return ("LoadControl", d)


def adaptive_analyze(m, total, steps, *, integrator=_default_integrator, adaptive=True, min_fraction=1.0 / 64,
                     grow_after=2, easy_iterations=None, breakpoints=(), on_step=None, rel_tol=1e-9):
    """Advance `m` (a beamsolid.Model or the beamsolid.opensees module, with its analysis set up)
    from progress 0 to `total` > 0.

    integrator(d) -> the integrator command's arguments for an increment d (default
    ("LoadControl", d)); on_step(progress, iterations) is called after every converged step.
    easy_iterations: a step is easy when it converged within this many iterations (default: any
    converged step is easy). Returns a StepperResult.
    """
    if not total > 0:
        raise ValueError(f"adaptive_analyze: total must be positive, got {total}")
    if steps < 1:
        raise ValueError(f"adaptive_analyze: steps must be at least 1, got {steps}")
    if not 0 < min_fraction <= 1:
        raise ValueError(f"adaptive_analyze: min_fraction must be in (0, 1], got {min_fraction}")
    nominal = total / steps
    h_min = nominal * min_fraction
    eps = rel_tol * total
    marks = sorted(b for b in breakpoints if eps < b < total - eps) + [total]
    r = StepperResult()
    h = nominal
    issued = None
    easy = 0
    while r.progress < total - eps:
        target = next(b for b in marks if b > r.progress + eps)
        h_try = min(h, target - r.progress)
        if target - r.progress - h_try < 0.01 * h_try:  # no sliver step before a breakpoint
            h_try = target - r.progress
        if h_try != issued:
            m.integrator(*integrator(h_try))
            issued = h_try
        code = m.analyze(1)
        if code == 0:
            iterations = int(m.testIter())
            r.progress = target if abs(target - (r.progress + h_try)) <= eps else r.progress + h_try
            r.steps += 1
            r.iterations.append(iterations)
            r.increments.append(h_try)
            if on_step is not None:
                on_step(r.progress, iterations)
            easy = easy + 1 if easy_iterations is None or iterations <= easy_iterations else 0
            if adaptive and h < nominal and easy >= grow_after:
                h = min(2.0 * h, nominal)
                r.grows += 1
                easy = 0
            continue
        r.failures += 1
        easy = 0
        if not adaptive or h_try <= h_min * (1.0 + 1e-12):
            r.failed_at = r.progress
            r.returncode = int(code)
            last_error = getattr(m, "last_error", None)
            r.error = last_error() if callable(last_error) else ""
            return r
        h = max(0.5 * h_try, h_min)
        r.cuts += 1
    r.converged = True
    return r
