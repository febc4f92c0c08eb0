"""Runs oracle scripts with OpenSeesPy and writes their results as JSON.

    python oracle_runner.py WORKDIR OUTPUT.json SCRIPT [SCRIPT ...]

Meant for the oracle interpreter (a Python where ``import openseespy`` works),
started in a subprocess: OpenSeesPy prints freely to stdout/stderr and may
call exit(), so the results travel through the JSON file only.
"""
import importlib
import json
import os
import sys
import traceback


def main(argv):
    workdir, output, names = argv[1], argv[2], argv[3:]
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import openseespy.opensees as ops

    results = {}
    for name in names:
        cwd = os.path.join(workdir, name)
        os.makedirs(cwd, exist_ok=True)
        here = os.getcwd()
        os.chdir(cwd)
        try:
            results[name] = importlib.import_module(name).run(ops)
        except Exception:  # noqa: BLE001 - reported to the caller
            results[name] = {"__error__": traceback.format_exc()}
        finally:
            os.chdir(here)
        # Write after every script so that a crash keeps what was done.
        with open(output, "w") as f:
            json.dump(results, f)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
