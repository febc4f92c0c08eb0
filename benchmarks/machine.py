"""What the benchmarks ran on: CPU, and the BLAS kernels under the sparse solvers.

Every benchmark writes this into its results: OpenBLAS picks its kernel at run time
(OPENBLAS_CORETYPE overrides a misdetection), and factorization speed depends on it.
"""
import ctypes
import os
import pathlib
import platform
import subprocess

import beamsolid


def openblas_in_use():
    """Version, build configuration and kernel of the OpenBLAS that SuiteSparse loaded in this process."""
    libs = set()
    with open("/proc/self/maps") as maps:
        for line in maps:
            path = line.split()[-1]
            if "openblas" in path and "scipy_openblas" not in path and path.endswith(tuple(".so" + s for s in
                                                                                           ("", ".0", ".3"))):
                libs.add(path)
    for path in sorted(libs):
        try:
            lib = ctypes.CDLL(path)
            lib.openblas_get_config.restype = ctypes.c_char_p
            lib.openblas_get_corename.restype = ctypes.c_char_p
            return path, lib.openblas_get_config().decode(), lib.openblas_get_corename().decode(), \
                lib.openblas_get_num_threads()
        except (OSError, AttributeError):
            continue
    return None


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
    """Markdown lines: CPU, the BLAS/LAPACK that UMFPACK and CHOLMOD link, the kernel loaded now."""
    lines = ["## Machine and BLAS", "", f"- CPU: {cpu_model()}, {os.cpu_count()} logical cores; Python "
             f"{platform.python_version()} on {platform.platform()}."]
    for name in ("libumfpack", "libcholmod"):
        path, deps = ldd_blas(name)
        lines.append(f"- `ldd {path}`:")
        lines += [f"  - `{d}`" for d in deps]
    blas = openblas_in_use()
    if blas:
        path, config, core, threads = blas
        lines += [f"- Loaded at run time: `{path}`: `{config}`, kernel **{core}**, {threads} threads "
                  f"(OPENBLAS_CORETYPE={os.environ.get('OPENBLAS_CORETYPE', 'unset')}, "
                  f"OPENBLAS_NUM_THREADS={os.environ.get('OPENBLAS_NUM_THREADS', 'unset')})."]
    else:
        lines.append("- No OpenBLAS loaded in this process (reference BLAS or not yet loaded).")
    lines += ["- NumPy's own OpenBLAS (`numpy.show_config()`) is a different library and does not run in "
              "these solves.", ""]
    return lines
