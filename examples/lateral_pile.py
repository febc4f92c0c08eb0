"""A single pile in elastic soil pushed laterally at its head (issue 5).

A thin wrapper of the scene (set-up, numbers and Randolph's closed form in docs/lateral_pile.md):

    python examples/lateral_pile.py --level coarse            # = python -m beamsolid.scenes lateral_pile
    python examples/lateral_pile.py --level medium --protocol cyclic --adaptive
"""
import os
import pathlib
import sys

from beamsolid.scenes.__main__ import main

if __name__ == "__main__":
    out = pathlib.Path(os.environ.get("BEAMSOLID_OUT", pathlib.Path(__file__).parent / "output")) / "lateral_pile"
    argv = sys.argv[1:]
    if "--out" not in argv:
        argv += ["--out", str(out)]
    sys.exit(main(["lateral_pile", *argv]))
