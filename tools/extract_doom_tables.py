"""Extracts DOOM's trigonometry tables (finetangent, finesine, tantoangle) from Chocolate
Doom's ``tables.c`` into ``wallbsp/data/doom/tables.json``, which ``wallbsp.doom.fixed`` loads.

    python tools/extract_doom_tables.py /work/src/choco/src/tables.c
"""
import json
import re
import sys
from pathlib import Path

OUT = Path(__file__).resolve().parent.parent / "wallbsp" / "data" / "doom" / "tables.json"
SIZES = {"finetangent": 4096, "finesine": 10240, "tantoangle": 2049}


def extract(source: str) -> dict:
    tables = {}
    for name, size in SIZES.items():
        m = re.search(r"\b%s\s*\[[^\]]*\]\s*=\s*\{(.*?)\};" % name, source, re.S)
        if not m:
            raise SystemExit(f"{name}: not found")
        values = [int(v) for v in re.findall(r"-?\d+", m.group(1))]
        if len(values) != size:
            raise SystemExit(f"{name}: {len(values)} values, expected {size}")
        tables[name] = values
    return tables


def main(argv):
    if len(argv) != 2:
        raise SystemExit(__doc__)
    tables = extract(Path(argv[1]).read_text(encoding="latin-1"))
    with open(OUT, "w") as f:
        json.dump(tables, f, separators=(",", ":"))
        f.write("\n")
    print(f"wrote {OUT}")


if __name__ == "__main__":
    main(sys.argv)
