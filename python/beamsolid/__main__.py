"""python -m beamsolid --cmake-dir | --include | --version | --plugin-abi | --blas

Where an out-of-tree plugin build finds BeamSolid (docs/plugins.md):
    cmake -S my_plugin -B build -DBeamSolid_DIR="$(python -m beamsolid --cmake-dir)"
"""
import argparse

import beamsolid


def main():
    parser = argparse.ArgumentParser(prog="python -m beamsolid", description=__doc__.splitlines()[0])
    what = parser.add_mutually_exclusive_group(required=True)
    what.add_argument("--cmake-dir", action="store_true", help="the folder of BeamSolidConfig.cmake")
    what.add_argument("--include", action="store_true", help="the folder of the C++ headers")
    what.add_argument("--version", action="store_true", help="the version")
    what.add_argument("--plugin-abi", action="store_true", help="the ABI stamp a plugin must carry")
    what.add_argument("--blas", action="store_true", help="the BLAS kernel in use, and why")
    args = parser.parse_args()
    if args.cmake_dir:
        print(beamsolid.cmake_dir())
    elif args.include:
        print(beamsolid.get_include())
    elif args.version:
        print(beamsolid.__version__)
    elif args.plugin_abi:
        print(beamsolid.plugin_abi())
    else:
        print(beamsolid.blas_info())


if __name__ == "__main__":
    main()
