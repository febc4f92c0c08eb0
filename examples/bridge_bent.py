"""The bridge bent of the paper's Figure 5: three piles and a cap beam pushed along the row.

Set-up and outputs: beamsolid/scenes/bridge_bent.py. Same as
`python -m beamsolid.scenes.bridge_bent --level coarse|medium|fine --out DIR`.

    python examples/bridge_bent.py --level medium
    python examples/render_bent.py out/bridge_bent_medium/bent.pvd docs/img/bridge_bent_contact.png
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))

from beamsolid.scenes.bridge_bent import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())
