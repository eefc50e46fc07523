"""Checks generated files with independent readers: the GeoTIFF with GDAL (rasterio)."""
import sys

import rasterio

path = sys.argv[1]
with rasterio.open(path) as d:
    assert d.crs.to_epsg() == 4326, d.crs
    b = d.bounds
    assert (b.left, b.bottom, b.right, b.top) == (-180.0, -90.0, 180.0, 90.0), b
    assert d.dtypes == ("float32",), d.dtypes
    a = d.read(1)
    assert a.shape == (d.height, d.width)
    assert -12000 < a.min() < 0 < a.max() < 15000, (a.min(), a.max())
print(f"{path}: EPSG:4326 {d.width}x{d.height} float32, {a.min():.0f}..{a.max():.0f} m")
