#pragma once

#include <QObject>
#include <QtQml/qqmlregistration.h>

namespace sortie::ui {

// What the map source dialog asks before it keeps a raster: can this file (or folder) be used as
// a DEM, or drawn as an orthophoto? Each answer is empty when it can, else the reason naming the
// file and GDAL's own words. Paths may be file:// URLs; an empty path is fine (none).
class RasterFileCheck : public QObject
{
    Q_OBJECT
    QML_ELEMENT

public:
    using QObject::QObject;

    Q_INVOKABLE QString demProblem(const QString &path) const;
    Q_INVOKABLE QString orthophotoProblem(const QString &path) const;
    // A file:// URL as a local path; anything else as it is.
    Q_INVOKABLE static QString localPath(const QString &pathOrUrl);
};

} // namespace sortie::ui
