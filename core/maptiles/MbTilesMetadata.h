#pragma once

#include "TileArea.h"

#include <QList>
#include <QPair>
#include <QString>
#include <QStringList>

#include <optional>

namespace sortie::maptiles {

// The metadata table of an MBTiles file, read leniently: what is readable is taken, what is not
// is named in `problems` ("maxzoom: 'x' is not a zoom level") and left missing, never guessed.
struct MbTilesMetadata
{
    QString name;
    QString attribution;
    QString description;
    QString format;                 // png, jpg, webp, ...
    QString version;
    std::optional<int> minZoom;
    std::optional<int> maxZoom;
    std::optional<GeoBounds> bounds;
    QList<QPair<QString, QString>> others; // every other key, as written
    QStringList problems;

    static MbTilesMetadata fromPairs(const QList<QPair<QString, QString>> &pairs);
    // Back to rows for writing: the known keys that are set, then the others.
    QList<QPair<QString, QString>> toPairs() const;
};

} // namespace sortie::maptiles
