#!/usr/bin/env python3
"""Map fidelity of a planet built from a global elevation map: the planet's elevation.tif
(equirectangular, any width) against the map box-averaged to the same grid, over land
(cells whose box average is >= 0 m), weighted by cell area. Prints Pearson r, mean bias, median absolute error, and
the hypsometry of both (median, 90th, 99th percentile of land altitude).

    python3 tools/map_fidelity.py OUT/elevation.tif MAP.tif
"""
import sys

import numpy as np
import tifffile


def box_average(a, shape):
    ky, kx = a.shape[0] // shape[0], a.shape[1] // shape[1]
    return a[: shape[0] * ky, : shape[1] * kx].reshape(shape[0], ky, shape[1], kx).mean(axis=(1, 3))


def main(planet_path, map_path):
    planet = tifffile.imread(planet_path).astype(np.float64)
    real = tifffile.imread(map_path).astype(np.float64)
    if real.shape[1] != 2 * real.shape[0] or real.shape[1] % planet.shape[1]:
        sys.exit(f"{map_path}: a global map is needed, a multiple of the planet raster's width; for a "
                 "regional map read map_fidelity in the planet's stats.json")
    ref = box_average(real, planet.shape)
    land = ref >= 0
    lat = 90 - (np.arange(planet.shape[0]) + 0.5) * 180 / planet.shape[0]
    w = np.repeat(np.cos(np.radians(lat))[:, None], planet.shape[1], axis=1)[land]
    p, m = planet[land], ref[land]
    mp, mm = np.average(p, weights=w), np.average(m, weights=w)
    r = np.average((p - mp) * (m - mm), weights=w) / np.sqrt(
        np.average((p - mp) ** 2, weights=w) * np.average((m - mm) ** 2, weights=w))
    bias = mp - mm
    err = np.abs(p - m)
    order = np.argsort(err)
    cw = np.cumsum(w[order])
    mae = err[order][np.searchsorted(cw, cw[-1] / 2)]
    print(f"land cells {land.sum()}  r {r:.4f}  bias {bias:+.1f} m  median |err| {mae:.1f} m")
    for name, a in (("planet", p), ("map", m)):
        print(f"  {name:6s} median {np.median(a):7.0f}  p90 {np.percentile(a, 90):7.0f}  p99 {np.percentile(a, 99):7.0f}")


if __name__ == "__main__":
    main(*sys.argv[1:3])
