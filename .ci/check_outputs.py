"""Checks generated files with independent readers: GeoTIFFs with GDAL (rasterio) and the COG
validator of rio-cogeo.

    python3 .ci/check_outputs.py ELEVATION.tif DEM.tif
"""
import sys

import numpy as np
import rasterio
from rio_cogeo.cogeo import cog_validate


def cloud_optimized(path):
    valid, errors, warnings = cog_validate(path, strict=True)
    assert valid and not errors and not warnings, (path, errors, warnings)


elevation, dem = sys.argv[1], sys.argv[2]
with rasterio.open(elevation) as d:
    assert d.crs.to_epsg() == 4326, d.crs
    b = d.bounds
    assert (b.left, b.bottom, b.right, b.top) == (-180.0, -90.0, 180.0, 90.0), b
    assert d.dtypes == ("float32",), d.dtypes
    assert d.nodata is None, d.nodata
    a = d.read(1)
    assert a.shape == (d.height, d.width)
    assert -12000 < a.min() < 0 < a.max() < 15000, (a.min(), a.max())
cloud_optimized(elevation)
print(f"{elevation}: COG, EPSG:4326 {d.width}x{d.height} float32, {a.min():.0f}..{a.max():.0f} m")

with rasterio.open(dem) as d:
    assert d.crs.to_epsg() == 4326, d.crs
    assert d.count == 2 and d.dtypes == ("float32", "float32"), d.dtypes
    assert d.descriptions == ("ground_m", "water_m"), d.descriptions
    assert np.isnan(d.nodata), d.nodata
    assert d.overviews(1), "overviews"
    ground, water = d.read(1), d.read(2)
    assert np.isfinite(ground).all(), "ground everywhere"
    wet = ~np.isnan(water)
    assert (water[wet] > ground[wet]).all(), "water stands above the ground"
    b = d.bounds
cloud_optimized(dem)
print(f"{dem}: COG, EPSG:4326 {d.width}x{d.height} 2 bands, bounds {tuple(round(v, 6) for v in b)}, "
      f"ground {ground.min():.0f}..{ground.max():.0f} m, {wet.mean():.1%} wet")
