"""What the benchmarks ran on: CPU, and the BLAS kernels under the sparse solvers.

Every benchmark writes this into its results: the kernel OpenBLAS runs (chosen at
beamsolid's import, beamsolid.blas_info() says which and why) sets the factorization speed.
"""
import os
import pathlib
import platform
import subprocess

import beamsolid


def ldd_blas(library_name):
    """The BLAS/LAPACK libraries a SuiteSparse library resolves to (ldd)."""
    ext = pathlib.Path(beamsolid.__file__).parent / "libbeamsolid.so"
    path = None
    for line in subprocess.run(["ldd", str(ext)], capture_output=True, text=True).stdout.splitlines():
        if library_name in line and "=>" in line:
            path = line.split("=>")[1].split()[0]
    if path is None:
        return library_name, []
    out = subprocess.run(["ldd", path], capture_output=True, text=True).stdout.splitlines()
    deps = [l.strip().split(" (")[0] for l in out if "blas" in l or "lapack" in l]
    return path, [d + (f"  [-> {os.path.realpath(d.split('=>')[1].strip())}]" if "=>" in d else "") for d in deps]


def cpu_model():
    try:
        for line in pathlib.Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def blas_report():
    """Markdown lines: CPU, the BLAS/LAPACK that UMFPACK and CHOLMOD link, the kernel loaded now and why.
    Printed too, so that a benchmark's console output says which kernels ran."""
    lines = ["## Machine and BLAS", "", f"- CPU: {cpu_model()}, {os.cpu_count()} logical cores; Python "
             f"{platform.python_version()} on {platform.platform()}."]
    for name in ("libumfpack", "libcholmod"):
        path, deps = ldd_blas(name)
        lines.append(f"- `ldd {path}`:")
        lines += [f"  - `{d}`" for d in deps]
    info = beamsolid.blas_info()
    if info.kernel:
        lines += [f"- Loaded at run time: `{info.library}`: `{info.config}`, kernel **{info.kernel}**, "
                  f"{info.threads} threads (OPENBLAS_CORETYPE={info.coretype or 'unset'}, "
                  f"OPENBLAS_NUM_THREADS={os.environ.get('OPENBLAS_NUM_THREADS', 'unset')}).",
                  f"- Why this kernel: {info.reason}."]
        if info.warning:
            lines.append(f"- Warning: {info.warning}.")
    else:
        lines.append(f"- No OpenBLAS loaded in this process: {info.reason}.")
    lines += ["- NumPy's own OpenBLAS (`numpy.show_config()`) is a different library and does not run in "
              "these solves.", ""]
    print("\n".join(lines))
    return lines
