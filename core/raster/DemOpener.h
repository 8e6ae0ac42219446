#pragma once

#include "ElevationSource.h"

#include <QString>
#include <QStringList>

#include <memory>

namespace sortie::raster {

// What --dem PATH and the terrain setting accept, opened as one elevation source:
// - an SRTM tile named NxxEyyy.hgt: the hand-written reader (HgtTileSource; docs/rasters.md says why);
// - any other file GDAL reads as a raster (GeoTIFF, COG, Copernicus DEM, DTED, VRT, ...): GdalDemSource;
// - a folder: its .hgt tiles through HgtTileSource and its other rasters (demFileSuffixes) through
//   IndexedDemSource (opened when first needed), both asked when it holds both.
// Null with an error naming the file and GDAL's reason when the path is unusable; in a folder, when
// no raster is usable (a bad raster among good ones is named in the source's problems()).
std::unique_ptr<terrain::ElevationSource> openDem(const QString &path, QString *error);

// File name suffixes (lower case, without the dot) a folder's rasters are picked by.
QStringList demFileSuffixes();

} // namespace sortie::raster
