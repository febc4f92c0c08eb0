"""The BLAS kernel under the sparse factorizations: chosen at import, reported by blas_info().

OpenBLAS reads ``OPENBLAS_CORETYPE`` once, when it loads, so the choice is made
before the package loads its solvers: the probe ``beamsolid_blas`` (built with
the package, the decision itself is C++: core/BlasKernel.cpp) runs once per
process tree with the variable removed, shows OpenBLAS's own pick, and the
result goes into this process's environment, where child processes find it.
"""
import dataclasses
import os
import pathlib
import subprocess
import warnings

CORETYPE = "OPENBLAS_CORETYPE"
CHOICE = "BEAMSOLID_BLAS_CHOICE"
PROBE = pathlib.Path(__file__).with_name("beamsolid_blas")


def _decode(text):
    kernel, reason, warning = (text.split("|", 2) + ["", ""])[:3]
    return kernel, reason, warning


def choose_kernel():
    """Set OPENBLAS_CORETYPE for this process tree (or leave it as it is), once."""
    setting = os.environ.get(CORETYPE, "")
    made = os.environ.get(CHOICE)
    if made is not None and _decode(made)[0] == setting:
        return
    if not PROBE.exists():
        os.environ[CHOICE] = f"{setting}|the probe {PROBE.name} is not installed: the kernel is OpenBLAS's own pick|"
        return
    env = {k: v for k, v in os.environ.items() if k != CORETYPE}
    env["OPENBLAS_NUM_THREADS"] = "1"  # the probe factors nothing: no thread pool to start
    try:
        done = subprocess.run([str(PROBE), setting], env=env, capture_output=True, text=True, timeout=60)
    except (OSError, subprocess.SubprocessError) as e:
        os.environ[CHOICE] = f"{setting}|the probe {PROBE.name} did not run ({e}): the kernel is left as it was|"
        return
    line = done.stdout.strip()
    if done.returncode != 0 or line.count("|") < 2:
        os.environ[CHOICE] = (f"{setting}|the probe {PROBE.name} failed (exit {done.returncode}): "
                              "the kernel is left as it was|")
        return
    kernel, _, warning = _decode(line)
    if kernel:
        os.environ[CORETYPE] = kernel
    else:
        os.environ.pop(CORETYPE, None)
    os.environ[CHOICE] = line
    if warning:
        warnings.warn("beamsolid: " + warning, RuntimeWarning, stacklevel=3)


@dataclasses.dataclass
class BlasInfo:
    """Which BLAS library and kernel run the factorizations, and why that kernel."""
    library: str
    config: str
    kernel: str
    kernel_requires: list
    threads: int
    cpu_vendor: str
    cpu_flags: list
    coretype: str
    reason: str
    warning: str

    def __str__(self):
        lines = [f"BLAS library: {self.library or 'not OpenBLAS'}"]
        if self.config:
            lines.append(f"build: {self.config}")
        if self.kernel:
            lines.append(f"kernel: {self.kernel} (needs {' '.join(self.kernel_requires) or 'nothing listed'}), "
                         f"{self.threads} thread{'s' if self.threads != 1 else ''}")
        lines.append(f"OPENBLAS_CORETYPE: {self.coretype or 'unset'}")
        lines.append(f"why: {self.reason}")
        if self.warning:
            lines.append(f"warning: {self.warning}")
        lines.append(f"CPU: {self.cpu_vendor}, {' '.join(self.cpu_flags)}")
        return "\n".join(lines)


def blas_info():
    """The BLAS library and kernel running in this process, and why that kernel was chosen."""
    from ._beamsolid import _blas_state

    state = _blas_state()
    _, reason, warning = _decode(os.environ.get(CHOICE, "||"))
    coretype = os.environ.get(CORETYPE, "")
    kernel = state.get("kernel", "")
    if coretype and kernel and coretype.upper() != kernel.upper():
        # OpenBLAS was loaded before beamsolid was imported, or ignored the name.
        reason += (f"; but {kernel} runs: OpenBLAS was loaded before the choice took effect, or does not know "
                   f"{coretype}")
    return BlasInfo(library=state.get("library", ""), config=state.get("config", ""), kernel=kernel,
                    kernel_requires=list(state.get("kernel_requires", [])), threads=int(state.get("threads", 0)),
                    cpu_vendor=state["cpu_vendor"], cpu_flags=list(state["cpu_flags"]), coretype=coretype,
                    reason=reason or "no choice was recorded", warning=warning)
