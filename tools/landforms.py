#!/usr/bin/env python3
"""Landforms below the map's resolution, measured against real terrain.

For each case a real DEM is box-averaged 4x and given to riverworld as the map; the planet's
`dem.tif` over the real DEM's grid is then compared with the real DEM by `landform.compare`
(the shared measurement script): the detail added below the map's resolution (std of planet
minus the bilinearly upsampled map, as a ratio to the real DEM's), median slope ratio, the
exponents of the radially averaged power spectra, and Pearson r.

Cases: the Jacksboro DEM (~90 m, Cumberland Mountains; the map is its 4x average, 360 m, as a
regional map) and crops of the ETOPO5 Earth DEM at 2048x1024 (~20 km; the map is the whole
Earth averaged to 512x256, and the planet's DEM is cut at the crop's 2048 grid): six the
landform's constants were fitted on and six held out. The `map r` column is the bilinearly
upsampled map's own r with the real DEM.

    python3 tools/landforms.py [--bin target/release/riverworld] [--shared ../shared] [--only NAME,...]
                               [--by-river]

Prints a Markdown table (one row per case) and writes the DEMs under target/landforms/. With
`--by-river`, then for each Earth crop: the std of the 4 x 4 block means of (planet - bilinear
map) against the same for the real DEM (the departure at the map's own pixels), and planet
minus real DEM by distance to the nearest cell with water on land (band 2 above the ground and
the sea; chessboard distance in cells).
"""
import argparse
import json
import os
import subprocess
import sys

import numpy as np
import tifffile

GEO_KEYS = [1, 1, 0, 4, 1024, 0, 1, 2, 1025, 0, 1, 1, 2048, 0, 1, 4326, 2054, 0, 1, 9102]

# Earth crops: name, west, south, east, north (degrees; multiples of the 2048 grid's 0.17578125°
# cells after snapping), what they show.
EARTH_CROPS = [
    ("himalaya", 76.0, 26.0, 98.0, 38.0, "mountain belt"),
    ("andes", -76.0, -34.0, -64.0, -14.0, "mountain belt"),
    ("alps", 2.0, 42.0, 18.0, 50.0, "mountain belt"),
    ("great_plains", -106.0, 34.0, -94.0, 46.0, "plains"),
    ("amazon", -70.0, -10.0, -56.0, 0.0, "lowland basin"),
    ("norway", 4.0, 58.0, 20.0, 68.0, "coast, fjords"),
]
# Crops never used to fit the landform's constants (added 2026-12-07 to see how the fit carries
# over): the rows the constants were fitted on are the ones above.
HELD_OUT_CROPS = [
    ("mississippi", -94.0, 30.0, -86.0, 38.0, "alluvial valley, Ozarks, Gulf shelf (held out)"),
    ("n_europe", 6.0, 50.0, 26.0, 56.0, "plain, North Sea and Baltic (held out)"),
    ("lake_eyre", 134.0, -32.0, 142.0, -24.0, "arid interior basin (held out)"),
    ("hudson", -92.0, 50.0, -80.0, 58.0, "shield lowland, shallow bay (held out)"),
    ("congo", 14.0, -6.0, 26.0, 4.0, "equatorial basin (held out)"),
    ("russian_plain", 30.0, 50.0, 50.0, 60.0, "plain (held out)"),
]


def box(a, k):
    h, w = a.shape[0] // k * k, a.shape[1] // k * k
    return a[:h, :w].reshape(h // k, k, w // k, k).mean(axis=(1, 3))


def write_geotiff(path, a, west, north, dx, dy):
    tifffile.imwrite(path, a.astype(np.float32), extratags=[
        (33550, "d", 3, (dx, dy, 0.0), False),
        (33922, "d", 6, (0.0, 0.0, 0.0, west, north, 0.0), False),
        (34735, "H", len(GEO_KEYS), GEO_KEYS, False),
    ])


def by_river(name, planet_path, real, coarse):
    """Where the planet departs from its map and from the real DEM: see the module's doc."""
    import rasterio
    from landform import upsample
    with rasterio.open(planet_path) as d:
        ground, water = d.read(1).astype(np.float64), d.read(2).astype(np.float64)
    up = upsample(coarse, real.shape)
    blocks = (box(ground - up, 4).std(), box(real - up, 4).std())
    wet = np.isfinite(water) & (water > ground) & (water > 0.01)
    # Chessboard distance to the nearest wet cell, by repeated 3 x 3 dilation.
    dist = np.where(wet, 0, np.inf)
    reached = wet.copy()
    for k in range(1, 7):
        grown = reached.copy()
        for dy in (-1, 0, 1):
            for dx in (-1, 0, 1):
                grown |= np.roll(np.roll(reached, dy, 0), dx, 1)
        dist[grown & ~reached] = k
        reached = grown
    dev = ground - real
    cells = []
    for lo, hi in ((0, 0), (1, 1), (2, 3), (4, 6), (7, np.inf)):
        m = (dist >= lo) & (dist <= hi)
        cells.append(f"{dev[m].mean():+.1f} ({dev[m].std():.1f}) m" if m.any() else "-")
    return f"| {name} | {blocks[0]:.1f} / {blocks[1]:.1f} m | " + " | ".join(cells) + " |"


def planet_dem(binary, map_path, bbox, width, height, out):
    extra = os.environ.get("RIVERWORLD_DEM_ARGS", "").split()
    cmd = [binary, "dem", *extra, "--map", map_path, "--bbox", ",".join(f"{v:.10f}" for v in bbox),
           "--width", str(width), "--height", str(height), "--out", out]
    res = subprocess.run(cmd, check=True, capture_output=True, text=True)
    stats = json.loads(res.stdout)
    import rasterio  # GDAL reads the COG (tifffile would need imagecodecs for its predictor)
    with rasterio.open(out) as d:
        return d.read(1).astype(np.float64), stats


def metres_per_degree():
    return 6_371_000 * np.pi / 180


def map_r(real, coarse):
    """Pearson r of the bilinearly upsampled map with the real DEM: what a planet that only
    interpolated its map would score, and about the most that detail uncorrelated with the real
    one leaves (docs/realism.md, "What r can reach")."""
    from landform import upsample
    return float(np.corrcoef(upsample(coarse, real.shape).ravel(), real.ravel())[0, 1])


def row(name, what, cmp, stats, r_map):
    ok = (0.6 <= cmp["detail_ratio"] <= 1.5, 0.75 <= cmp["slope_ratio"] <= 1.33,
          abs(cmp["beta_planet"] - cmp["beta_real"]) <= 0.5, cmp["r"] >= 0.95)
    mark = lambda good: "" if good else " ✗"
    return (f"| {name} | {what} | {cmp['detail_real_m']:.0f} | {cmp['detail_ratio']:.2f}{mark(ok[0])} | "
            f"{cmp['slope_ratio']:.2f}{mark(ok[1])} | {cmp['beta_real']:.2f} / {cmp['beta_planet']:.2f}{mark(ok[2])} | "
            f"{cmp['r']:.3f}{mark(ok[3])} | {r_map:.3f} | {stats['total_ms']:.0f} |")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", default="target/release/riverworld")
    ap.add_argument("--shared", default="../shared")
    ap.add_argument("--only")
    ap.add_argument("--by-river", action="store_true")
    args = ap.parse_args()
    sys.path.insert(0, os.path.join(args.shared, "tools"))
    from landform import compare

    out = "target/landforms"
    os.makedirs(out, exist_ok=True)
    print("| case | terrain | real detail (m) | detail ratio | slope ratio | beta real / planet | r | map r | dem ms |")
    print("|---|---|---|---|---|---|---|---|---|")

    # Jacksboro: regional map, 4x average of the 90 m DEM (and, beyond the protocol, 16x: 1.4 km
    # map pixels, so that eight bisections of detail lie between the map and the DEM).
    for name, k in (("jacksboro", 4), ("jacksboro_16x", 16)):
        if args.only and name not in args.only.split(","):
            continue
        meta = json.load(open(os.path.join(args.shared, "maps/region_jacksboro_tn_403x344.json")))
        real = tifffile.imread(os.path.join(args.shared, "maps", meta["geotiff"])).astype(np.float64)
        real = real[:344, :400]
        b = meta["bounds_deg"]
        d = meta["pixel_size_deg"][0]
        west, north = b["west"], b["north"]
        east, south = west + 400 * d, north - 344 * d
        coarse = box(real, k)
        map_path = f"{out}/{name}_map.tif"
        write_geotiff(map_path, coarse, west, north, k * d, k * d)
        planet, stats = planet_dem(args.bin, map_path, (west, south, east, north), 400, 344, f"{out}/{name}_dem.tif")
        dy = d * metres_per_degree()
        dx = dy * np.cos(np.radians((north + south) / 2))
        cmp = compare(planet, real, coarse, dx, dy)
        print(row(name, f"Appalachian ridges, 90 m, map {k}x", cmp, stats, map_r(real, coarse)))

    # Earth crops: global map = ETOPO5 2048 averaged 4x.
    earth = tifffile.imread(os.path.join(args.shared, "maps/earth_etopo5_2048x1024.tif")).astype(np.float64)
    d = 360 / earth.shape[1]
    map_path = f"{out}/earth_512_map.tif"
    if not os.path.exists(map_path):
        write_geotiff(map_path, box(earth, 4), -180.0, 90.0, 4 * d, 4 * d)
    rivers = []
    for name, w, s, e, n, what in EARTH_CROPS + HELD_OUT_CROPS:
        if args.only and name not in args.only.split(","):
            continue
        c0, c1 = round((w + 180) / d / 4) * 4, round((e + 180) / d / 4) * 4
        r0, r1 = round((90 - n) / d / 4) * 4, round((90 - s) / d / 4) * 4
        real = earth[r0:r1, c0:c1]
        bbox = (-180 + c0 * d, 90 - r1 * d, -180 + c1 * d, 90 - r0 * d)
        planet, stats = planet_dem(args.bin, map_path, bbox, c1 - c0, r1 - r0, f"{out}/{name}_dem.tif")
        coarse = box(real, 4)
        dy = d * metres_per_degree()
        dx = dy * np.cos(np.radians((bbox[1] + bbox[3]) / 2))
        print(row(name, what, compare(planet, real, coarse, dx, dy), stats, map_r(real, coarse)))
        if args.by_river:
            rivers.append(by_river(name, f"{out}/{name}_dem.tif", real, coarse))
    if rivers:
        print("\n| crop | block means' std, planet / real | on water | 1 cell | 2-3 | 4-6 | 7 and more |")
        print("|---|---:|---:|---:|---:|---:|---:|")
        print("\n".join(rivers))


if __name__ == "__main__":
    main()
