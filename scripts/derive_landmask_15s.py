#!/usr/bin/python3
"""Derives the embedded GSHHG land mask in two levels from the high-resolution shorelines.

GSHHG-h (Debian gmt-gshhg-high) rasterised by GMT's grdlandmask at 15" (about 460 m) in 10 deg
tiles, pixel registration, 1 = land (lakes as water, islands in lakes as land, ponds in those
as water: GMT levels 1 and 3), then packed per 2' cell (8 x 8 cells of 15"):

  data/gshhg_landmask_2m.png            the 2' mask, each cell the majority of its 64 fine cells
                                        (32 or more land: land), 1-bit PNG, north row first
                                        (its world file, gshhg_landmask_2m.pgw, is unchanged)
  data/gshhg_landmask_15s_refined.png   1 where the cell's 64 fine cells are not all one class
                                        (the same grid and layout as the 2' mask)
  data/gshhg_landmask_15s_blocks.bin.gz the refined cells' 8 x 8 blocks, 64-bit little-endian
                                        words in row-major order of their 2' cells (rows south
                                        to north, columns west to east from 180 W); bit
                                        8 j + i = the fine cell i columns east of the block's
                                        west edge and j rows north of its south edge; gzip with
                                        no name and no time stamp, so the bytes are reproducible

data::LandMask reads them (the fine level where a pixel's footprint resolves it). About 33 CPU
minutes (two tiles at a time by default). Needs gmt, gmt-gshhg-high, python3-numpy, python3-gdal.

Usage: scripts/derive_landmask_15s.py [DATA_DIR] [--jobs N]
"""
import argparse
import gzip
import multiprocessing
import os
import subprocess
import sys
import tempfile

import numpy as np
from osgeo import gdal

TILE_DEG = 10
FINE_PER_DEG = 240   # 15" cells per degree
PER_CELL = 8         # 15" cells per 2' cell
COARSE_PER_DEG = FINE_PER_DEG // PER_CELL
GMT_HEADER_BYTES = 892  # GMT's native binary grid header (format =bb)


def tile(args):
    """One 10 deg tile: (row0, col0, majority, mixed, blocks) of its 2' cells, rows south first."""
    south, west = args
    n = TILE_DEG * FINE_PER_DEG
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "tile.bin")
        region = f"{west}/{west + TILE_DEG}/{south}/{south + TILE_DEG}"
        subprocess.run(["gmt", "grdlandmask", f"-R{region}", "-I15s", "-Dh", "-N0/1/0/1/0", "-r",
                        f"-G{out}=bb"], check=True, cwd=tmp)  # cwd: GMT's gmt.history there
        raw = np.fromfile(out, dtype=np.uint8)
    if raw.size != GMT_HEADER_BYTES + n * n:
        raise RuntimeError(f"tile {region}: {raw.size} bytes, expected {GMT_HEADER_BYTES + n * n}")
    fine = raw[GMT_HEADER_BYTES:].reshape(n, n)[::-1]  # rows south to north
    m = n // PER_CELL
    # blocks[r, c, j, i]: fine cell i east, j north within 2' cell (c, r).
    blocks = fine.reshape(m, PER_CELL, m, PER_CELL).transpose(0, 2, 1, 3).astype(np.uint64)
    weights = (np.uint64(1) << np.arange(64, dtype=np.uint64)).reshape(PER_CELL, PER_CELL)
    words = (blocks * weights).sum(axis=(2, 3), dtype=np.uint64)
    count = blocks.sum(axis=(2, 3))
    row0 = (south + 90) * COARSE_PER_DEG
    col0 = (west + 180) * COARSE_PER_DEG
    return row0, col0, count >= 32, (count > 0) & (count < 64), words


def write_bit_png(path, bits_south_first):
    rows, cols = bits_south_first.shape
    mem = gdal.GetDriverByName("MEM").Create("", cols, rows, 1, gdal.GDT_Byte)
    mem.GetRasterBand(1).WriteArray(bits_south_first[::-1].astype(np.uint8))
    gdal.GetDriverByName("PNG").CreateCopy(path + ".tmp", mem, options=["NBITS=1"])
    if os.path.exists(path + ".tmp.aux.xml"):
        os.remove(path + ".tmp.aux.xml")
    os.replace(path + ".tmp", path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("data_dir", nargs="?", default=os.path.join(os.path.dirname(__file__), "..", "data"))
    parser.add_argument("--jobs", type=int, default=2)
    args = parser.parse_args()
    rows, cols = 180 * COARSE_PER_DEG, 360 * COARSE_PER_DEG
    majority = np.zeros((rows, cols), dtype=bool)
    mixed = np.zeros((rows, cols), dtype=bool)
    words = np.zeros((rows, cols), dtype=np.uint64)
    tiles = [(s, w) for s in range(-90, 90, TILE_DEG) for w in range(-180, 180, TILE_DEG)]
    m = TILE_DEG * COARSE_PER_DEG
    with multiprocessing.Pool(args.jobs) as pool:
        for done, (r0, c0, maj, mix, wd) in enumerate(pool.imap_unordered(tile, tiles), 1):
            majority[r0:r0 + m, c0:c0 + m] = maj
            mixed[r0:r0 + m, c0:c0 + m] = mix
            words[r0:r0 + m, c0:c0 + m] = wd
            print(f"\rderive_landmask_15s: {done}/{len(tiles)} tiles", end="", file=sys.stderr, flush=True)
    print(file=sys.stderr)
    stem = os.path.join(args.data_dir, "gshhg_landmask_")
    write_bit_png(stem + "2m.png", majority)
    write_bit_png(stem + "15s_refined.png", mixed)
    blocks = words[mixed].astype("<u8").tobytes()  # row-major: rows south first, then columns
    with open(stem + "15s_blocks.bin.gz.tmp", "wb") as f:
        with gzip.GzipFile(filename="", mode="wb", fileobj=f, compresslevel=9, mtime=0) as z:
            z.write(blocks)
    os.replace(stem + "15s_blocks.bin.gz.tmp", stem + "15s_blocks.bin.gz")
    print(f"derive_landmask_15s: {int(mixed.sum())} refined 2' cells of {rows * cols}, "
          f"{int(majority.sum())} land; wrote {stem}2m.png, {stem}15s_refined.png, "
          f"{stem}15s_blocks.bin.gz", file=sys.stderr)


if __name__ == "__main__":
    main()
