"""Run a scene: python -m beamsolid.scenes NAME --level coarse|medium|fine [--out DIR] [--adaptive] ...

Each scene prints a short table, writes recorder files and a VTK time series into --out and
saves PNG plots there. Registering a scene is one line in SCENES: its name, the module and
function that run it (imported only when chosen), and a one-line description. The function
takes the parsed options it knows as keyword arguments (level, out, adaptive, steps, ...).
"""
import argparse
import importlib
import inspect
import sys

SCENES = {
    "lateral_pile": ("beamsolid.scenes.lateral_pile", "scene", "a pile in elastic soil pushed laterally at its head"),
    "donut_pullout": ("beamsolid.scenes.donut_cli", "scene", "the donut pullout test (paper's Table 1)"),
    "bridge_bent": ("beamsolid.scenes.bridge_bent", "scene", "piles joined by a cap beam, pushed transversely"),
    "seismic_pile": ("beamsolid.scenes.seismic_pile", "scene", "a pile in a soil layer shaken at the bedrock"),
    "lateral_capacity": ("beamsolid.scenes.lateral_capacity", "scene",
                         "a free-head pile in von Mises clay pushed to failure, four ways"),
}


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python -m beamsolid.scenes", description=__doc__.splitlines()[0])
    parser.add_argument("name", choices=sorted(SCENES), help="; ".join(f"{k}: {v[2]}" for k, v in SCENES.items()))
    parser.add_argument("--level", choices=("coarse", "medium", "fine"), default="coarse", help="mesh level")
    parser.add_argument("--out", default=None, help="output directory (default: NAME_output)")
    parser.add_argument("--adaptive", action="store_true", help="cut the step on failure, grow it back")
    parser.add_argument("--steps", type=int, default=None, help="steps (per quarter cycle when cyclic)")
    parser.add_argument("--interface", choices=("contact", "penalty", "tied", "py"), default=None,
                        help="seismic_pile: py is the beam on p-y springs; the scene also runs tied and py beside it")
    parser.add_argument("--head-mass", type=float, default=None, help="seismic_pile: mass at the pile head (t)")
    parser.add_argument("--scale", type=float, default=None, help="seismic_pile: factor on the record")
    parser.add_argument("--protocol", choices=("monotonic", "cyclic"), default=None)
    parser.add_argument("--cycles", type=int, default=None)
    parser.add_argument("--algorithm", choices=("Newton", "NewtonLineSearch", "KrylovNewton"), default=None)
    args = parser.parse_args(argv)
    module, function, _ = SCENES[args.name]
    run = getattr(importlib.import_module(module), function)
    options = {k: v for k, v in vars(args).items() if k != "name" and v is not None and v is not False}
    options.setdefault("out", f"{args.name}_output")
    accepted = inspect.signature(run).parameters
    ignored = sorted(k for k in options if k not in accepted)
    if ignored:
        parser.error(f"scene {args.name} does not take --{', --'.join(ignored)}")
    run(**options)
    return 0


if __name__ == "__main__":
    sys.exit(main())
