#!/usr/bin/env bash
# Writes the seed corpus of fuzz_raster (tiny GeoTIFFs, committed in raster-corpus/) with GDAL's
# command-line tools (gdal-bin): a DEM in degrees with a nodata pixel, one in UTM, an RGB image in
# Web Mercator, a rotated raster, a tiled one with an overview. Run from anywhere; rewrites the seeds.
# regress-*.tif are inputs that once failed (kept as they are, not written here).
set -euo pipefail
out="$(cd "$(dirname "$0")" && pwd)/raster-corpus"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"
quiet() { "$@" > /dev/null; }
cat > "$work/dem.asc" <<'GRID'
ncols 4
nrows 4
xllcorner 24.0
yllcorner 56.0
cellsize 0.25
NODATA_value -9999
10 11 12 13
20 21 -9999 23
30 31 32 33
40 41 42 43
GRID
quiet gdal_translate -q -of GTiff -ot Float32 -a_srs EPSG:4326 "$work/dem.asc" "$out/dem-4326-nodata.tif"
quiet gdal_translate -q -of GTiff -ot Int16 -a_srs EPSG:32635 -a_ullr 300000 6300000 300090 6299910 -outsize 3 3 "$work/dem.asc" "$out/dem-utm.tif"
quiet gdal_translate -q -of GTiff -ot Byte -a_srs EPSG:3857 -b 1 -b 1 -b 1 -a_nodata none -scale 10 43 0 255 "$work/dem.asc" "$out/rgb-3857.tif"
quiet gdal_translate -q -of GTiff -ot Float32 -co TILED=YES -co BLOCKXSIZE=16 -co BLOCKYSIZE=16 -co COMPRESS=DEFLATE -a_srs EPSG:4326 -outsize 32 32 "$work/dem.asc" "$work/tiled.tif"
quiet gdaladdo -q -r average --config COMPRESS_OVERVIEW DEFLATE "$work/tiled.tif" 2
cp "$work/tiled.tif" "$out/tiled-overview.tif"
# Rotated by 30°: a VRT carries the turned geotransform into the GeoTIFF.
quiet gdal_translate -q -of VRT "$out/dem-4326-nodata.tif" "$work/rotated.vrt"
sed -i 's|<GeoTransform>.*</GeoTransform>|<GeoTransform>24.0, 0.2165, 0.125, 57.0, 0.125, -0.2165</GeoTransform>|' "$work/rotated.vrt"
quiet gdal_translate -q -of GTiff "$work/rotated.vrt" "$out/rotated.tif"
ls -l "$out"
