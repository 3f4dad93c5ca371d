"""Write docs/maps_sheet.png: every stdlib graph's outputs, labelled.

.venv/bin/python bench/maps_sheet.py [--size 256] [--out docs/maps_sheet.png]
"""

import argparse
from pathlib import Path

from cnlmc.backends.maps import render_contact_sheet


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=256)
    parser.add_argument("--out", default=str(Path(__file__).resolve().parents[1] / "docs" / "maps_sheet.png"))
    args = parser.parse_args()
    print(render_contact_sheet(args.out, args.size))


if __name__ == "__main__":
    main()
