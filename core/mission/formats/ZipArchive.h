#pragma once

#include "MissionError.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <memory>
#include <vector>

namespace sortie::mission::formats {

// A file in a ZIP archive (a KMZ is one): its path inside the archive and its bytes.
struct ZipEntry
{
    QString path;
    QByteArray data;
};

// What reading an archive may cost. An archive from outside is hostile until read: its sizes and
// offsets are claims. Entries are inflated only when asked for, each within `maxEntryBytes`, all of
// them together within `maxTotalBytes` (an entry read twice counts twice), and an entry that
// inflates more than `maxRatio` times its compressed size beyond `ratioFloorBytes` is refused
// before it is inflated (a few kilobytes of zeros that claim gigabytes).
struct ZipLimits
{
    qint64 maxEntryBytes = 64 * 1024 * 1024;
    qint64 maxTotalBytes = 128 * 1024 * 1024;
    int maxEntries = 4096;
    double maxRatio = 200;                   // XML deflates 5–30×; zeros 1,000×
    qint64 ratioFloorBytes = 1024 * 1024;    // smaller entries may have any ratio
};

// Reads a ZIP archive held in memory through libzip (CRCs, compression methods and the central
// directory are libzip's). On top of it: the limits above, and entries whose bytes overlap (two
// names for one stored body, the trick that makes a small archive inflate many times) are refused
// when the archive is opened. libzip does not give the entries' offsets, so those are read from the
// central directory libzip has already checked (see ZipArchive.cpp).
class ZipReader
{
public:
    static Result<ZipReader> open(const QByteArray &archive, ZipLimits limits = {});
    ZipReader(ZipReader &&) noexcept;
    ZipReader &operator=(ZipReader &&) noexcept;
    ~ZipReader();

    // The files in the archive, in its order (directories left out).
    QStringList paths() const;
    // One file's bytes, checked against its CRC and the limits.
    Result<QByteArray> read(const QString &path);
    // Bytes inflated so far (what the total limit counts).
    qint64 inflatedBytes() const;

private:
    struct State;
    explicit ZipReader(std::unique_ptr<State> state);
    std::unique_ptr<State> m_state;
};

// Writes a ZIP archive through libzip: each entry deflated, UTF-8 names, fixed timestamps (the same
// entries give the same bytes).
Result<QByteArray> writeZip(const std::vector<ZipEntry> &entries);

// Every file of an archive, within the limits (for tests and tools that want them all).
Result<std::vector<ZipEntry>> readZip(const QByteArray &archive, ZipLimits limits = {});

} // namespace sortie::mission::formats
