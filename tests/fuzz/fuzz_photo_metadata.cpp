// Photos' metadata through exiv2 (sortie-log geotag PHOTO_DIR): any bytes, written to a file, are
// read into a PhotoInfo or refused with a reason, never an exception or a crash; a photo read has
// no size or focal length that is 0 or less (absent instead). A geotagged copy of what was read is
// written and read again. Seeds: JPEGs written by tests/geotag's helpers (QImage, exiv2 tags), one
// geotagged copy, and damaged ones.
#include "PhotoMetadata.h"

#include <QDir>
#include <QFile>

#include <cstdio>
#include <cstdlib>
#include <unistd.h>

using namespace sortie::geotag;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const QString path = QDir::temp().filePath(QStringLiteral("fuzz-%1.jpg").arg(getpid()));
    {
        QFile file(path);
        if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate))
            std::abort();
        file.write(reinterpret_cast<const char *>(data), qint64(size));
    }
    QString error;
    const auto info = PhotoMetadataFile::read(path, &error);
    if (!info) {
        if (error.isEmpty())
            std::abort();
        return 0;
    }
    if ((info->width && *info->width <= 0) || (info->height && *info->height <= 0) || (info->focalLengthMm && !(*info->focalLengthMm > 0)))
        std::abort();
    GeoTag tag{56.95, 24.1, 40.0, 20.0, info->cameraTimeUtc.value_or(0)};
    if (PhotoMetadataFile::writeGeoTag(path, tag, &error) && !PhotoMetadataFile::read(path, &error)) {
        fprintf(stderr, "written, then not read: %s\n", qPrintable(error));
        std::abort(); // what exiv2 wrote, it reads
    }
    return 0;
}
