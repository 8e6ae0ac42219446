#pragma once

#include <QObject>
#include <QString>
#include <QtQml/qqmlregistration.h>

namespace sortie::ui {

// What checking a DEM path found: why it cannot be used; or, when it can, the files in it that
// are left out (a folder with a few bad rasters among good ones), each with its reason.
struct DemCheck
{
    Q_GADGET
    QML_VALUE_TYPE(demCheck)
    Q_PROPERTY(QString problem MEMBER problem)
    Q_PROPERTY(QString leftOut MEMBER leftOut)

public:
    QString problem;
    QString leftOut;
};

// What the map source dialog asks before it keeps a raster: can this file (or folder) be used as
// a DEM, or drawn as an orthophoto? A problem is empty when it can, else the reason naming the
// file and GDAL's own words. Paths may be file:// URLs; an empty path is fine (none).
class RasterFileCheck : public QObject
{
    Q_OBJECT
    QML_ELEMENT

public:
    using QObject::QObject;

    Q_INVOKABLE sortie::ui::DemCheck checkDem(const QString &path) const;
    Q_INVOKABLE QString orthophotoProblem(const QString &path) const;
    // A file:// URL as a local path; anything else as it is.
    Q_INVOKABLE static QString localPath(const QString &pathOrUrl);
};

} // namespace sortie::ui
