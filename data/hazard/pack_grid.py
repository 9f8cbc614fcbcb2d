"""Packs the official hazard grid into the rocking-codes crate, which embeds it.

Writes ../../crates/rocking-codes/data/ntc2018-tabella1.zlib (Tabella 1, this
folder's ntc2008-allegato-b-tabella1-with-id.txt, deflated in the zlib format:
1.73 MB of text in about 437 kB) and ../../crates/rocking-codes/data/ntc2018-tabella2.txt
(Tabella 2, the islands, copied as it is). The crate's tests check that both
give back this folder's files byte for byte. Run from this folder:

    python3 pack_grid.py
"""

import pathlib
import shutil
import zlib

HERE = pathlib.Path(__file__).resolve().parent
OUT = HERE.parent.parent / "crates" / "rocking-codes" / "data"

table = (HERE / "ntc2008-allegato-b-tabella1-with-id.txt").read_bytes()
packed = zlib.compress(table, 9)
(OUT / "ntc2018-tabella1.zlib").write_bytes(packed)
shutil.copyfile(HERE / "ntc2008-allegato-b-tabella2-isole.txt", OUT / "ntc2018-tabella2.txt")
print(f"Tabella 1: {len(table)} bytes packed in {len(packed)}")
