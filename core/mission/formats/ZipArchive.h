#pragma once

#include "MissionError.h"

#include <QByteArray>
#include <QString>

#include <vector>

namespace sortie::mission::formats {

// A file in a ZIP archive (a KMZ is one): its path inside the archive and its bytes.
struct ZipEntry
{
    QString path;
    QByteArray data;
};

// Writes a ZIP archive (PKWARE APPNOTE 6.3): each entry deflated with zlib (stored when that is
// not smaller), CRC-32 checked, UTF-8 names, no ZIP64 (refused by returning an error when an entry
// or the archive would pass 4 GiB, which no route comes near). Deterministic: fixed timestamps.
Result<QByteArray> writeZip(const std::vector<ZipEntry> &entries);

// Reads every file of a ZIP archive (stored or deflated entries; directories skipped), checking
// each CRC-32 and size. A truncated or corrupt archive fails with what is wrong and where. Entries
// larger than maxEntryBytes are refused rather than inflated (a ZIP bomb stays small in memory).
Result<std::vector<ZipEntry>> readZip(const QByteArray &archive, qint64 maxEntryBytes = 64 * 1024 * 1024);

} // namespace sortie::mission::formats
