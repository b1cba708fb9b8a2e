"""``python -m orchard_world.model [--json] FILE...``: what model files hold, as ``./orchard model-info`` prints it."""
from __future__ import annotations

import argparse
import sys
from typing import List, Optional

from . import ModelError, read


def main(argv: Optional[List[str]] = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m orchard_world.model",
        description="List model files' joints, clips, size and units (glTF, X3D, VRML97, a zip of a model's files), "
                    "offline; --json prints one JSON object a line, the fields of ./orchard model-info --json.")
    parser.add_argument("files", nargs="+", metavar="FILE", help="model files: .gltf, .glb, .x3d, .wrl or .zip")
    parser.add_argument("--json", action="store_true", help="print one JSON object a file instead of text")
    args = parser.parse_args(argv)
    status = 0
    for file in args.files:
        try:
            info = read(file)
        except (ModelError, OSError) as e:
            print(f"error: {e}", file=sys.stderr)
            status = max(status, 2 if isinstance(e, OSError) or "expected a model file" in str(e) else 1)
            if args.json:
                print("null")
            continue
        sys.stdout.write(info.to_json() + "\n" if args.json else info.to_text())
    return status


if __name__ == "__main__":
    sys.exit(main())
