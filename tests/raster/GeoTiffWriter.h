#pragma once

// Writes small GeoTIFFs for the tests with GDAL's own API: any CRS, any number of bands, optional
// nodata, optional overviews.
#include <cpl_string.h>
#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <QString>

#include <functional>
#include <optional>
#include <vector>

namespace sortie::raster::test {

struct GeoTiffSpec
{
    int width = 0, height = 0;
    double geoTransform[6] = {};  // x0, pixel width, 0, y0, 0, -pixel height (GDAL's order)
    QString crs = QStringLiteral("EPSG:4326");  // anything SetFromUserInput takes ("EPSG:32635", "EPSG:4326+5773")
    int bands = 1;
    GDALDataType type = GDT_Float32;
    std::optional<double> noData;
    bool alphaLast = false;     // the last band is alpha
    bool tiled = false;         // 256×256 blocks, as a COG has
    std::vector<int> overviews; // decimation factors to build (AVERAGE)
};

// value(band, row, column), band from 0. False when GDAL refuses.
inline bool writeGeoTiff(const QString &path, const GeoTiffSpec &spec, const std::function<double(int, int, int)> &value)
{
    GDALAllRegister();
    GDALDriver *driver = GetGDALDriverManager()->GetDriverByName("GTiff");
    CPLStringList options;
    if (spec.tiled)
        options.SetNameValue("TILED", "YES");
    GDALDataset *ds = driver->Create(path.toUtf8().constData(), spec.width, spec.height, spec.bands, spec.type, options.List());
    if (!ds)
        return false;
    double gt[6];
    std::copy(spec.geoTransform, spec.geoTransform + 6, gt);
    ds->SetGeoTransform(gt);
    OGRSpatialReference srs;
    srs.SetFromUserInput(spec.crs.toUtf8().constData());
    ds->SetSpatialRef(&srs);
    std::vector<double> row(size_t(spec.width));
    for (int b = 0; b < spec.bands; ++b) {
        GDALRasterBand *band = ds->GetRasterBand(b + 1);
        if (spec.noData)
            band->SetNoDataValue(*spec.noData);
        if (spec.alphaLast && b == spec.bands - 1)
            band->SetColorInterpretation(GCI_AlphaBand);
        for (int r = 0; r < spec.height; ++r) {
            for (int c = 0; c < spec.width; ++c)
                row[size_t(c)] = value(b, r, c);
            if (band->RasterIO(GF_Write, 0, r, spec.width, 1, row.data(), spec.width, 1, GDT_Float64, 0, 0) != CE_None) {
                GDALClose(ds);
                return false;
            }
        }
    }
    bool ok = true;
    if (!spec.overviews.empty())
        ok = ds->BuildOverviews("AVERAGE", int(spec.overviews.size()), spec.overviews.data(), 0, nullptr, nullptr, nullptr) == CE_None;
    GDALClose(ds);
    return ok;
}

} // namespace sortie::raster::test
