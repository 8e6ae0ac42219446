#pragma once

#include "ElevationSource.h"
#include "RasterFootprint.h"

#include <QStringList>

#include <list>
#include <memory>
#include <unordered_map>
#include <vector>

namespace sortie::raster {

class DemRaster;

// Terrain from a folder of many elevation rasters (a national DEM in thousands of GeoTIFF tiles).
// Opening reads each file's header once (size, geotransform, CRS), keeps its WGS-84 box in an R-tree
// and closes it again; a file is opened (DemRaster) only when a point falls in its box, and at most
// `maxOpen` stay open, the least recently used closed first (which frees its chunks and GDAL's block
// cache). Among the files whose box holds a point, the one that answered last is asked first, then
// the others in the order given; the first value wins. A file that cannot be used is named once in
// problems() with GDAL's reason, and the others still answer.
class IndexedDemSource : public terrain::ElevationSource
{
    Q_OBJECT

public:
    static constexpr int kDefaultMaxOpen = 16;

    // Null, with the first file's error, when not one of `files` can be used.
    static std::unique_ptr<IndexedDemSource> open(const QString &displayPath, const QStringList &files, QString *error,
                                                  int maxOpen = kDefaultMaxOpen);
    ~IndexedDemSource() override;

    QString name() const override;
    terrain::ElevationSample sample(const terrain::GeoPoint &point) override;
    QStringList problems() const override { return m_problems; }

    // The files in the index, those open now, and how many times a file was opened to be sampled.
    int indexedCount() const { return int(m_entries.size()); }
    int openCount() const { return int(m_open.size()); }
    int maxOpen() const { return m_maxOpen; }
    long opens() const { return m_opens; }

private:
    struct Entry
    {
        QString path;
        GeoBox box;
        bool broken = false;      // failed to open when first asked: named in problems(), never retried
        bool openedBefore = false;  // its vertical datum logged already
    };
    struct OpenRaster
    {
        std::unique_ptr<DemRaster> raster;
        std::list<int>::iterator place;
    };
    class Tree;

    IndexedDemSource();
    void buildTree();
    // The entry's raster, opened now if it is not; null when it cannot be opened.
    DemRaster *raster(int entry);
    terrain::ElevationSample sampleEntry(int entry, double latitude, double longitude);
    void addProblem(const QString &problem);

    QString m_displayPath;
    int m_maxOpen = kDefaultMaxOpen;
    std::vector<Entry> m_entries;
    std::unique_ptr<Tree> m_tree;
    std::vector<int> m_candidates;  // reused by sample()
    std::list<int> m_recent;        // open entries, most recent first
    std::unordered_map<int, OpenRaster> m_open;
    int m_last = -1;
    long m_opens = 0;
    QStringList m_problems;
};

} // namespace sortie::raster
