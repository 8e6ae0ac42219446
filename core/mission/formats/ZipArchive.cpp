#include "ZipArchive.h"

#include <QtEndian>

#include <zlib.h>

#include <limits>

namespace sortie::mission::formats {
namespace {

constexpr quint32 kLocalHeader = 0x04034b50;
constexpr quint32 kCentralHeader = 0x02014b50;
constexpr quint32 kEndOfCentralDirectory = 0x06054b50;
constexpr quint16 kStored = 0;
constexpr quint16 kDeflated = 8;
constexpr quint16 kUtf8Names = 1 << 11;
constexpr quint16 kVersion = 20;  // 2.0: deflate
// 1980-01-01 00:00 in MS-DOS format: archives do not change when nothing in them changed.
constexpr quint16 kDosTime = 0;
constexpr quint16 kDosDate = (0 << 9) | (1 << 5) | 1;

void put16(QByteArray &out, quint16 v) { char b[2]; qToLittleEndian(v, b); out.append(b, 2); }
void put32(QByteArray &out, quint32 v) { char b[4]; qToLittleEndian(v, b); out.append(b, 4); }

MissionError zipError(const QString &message) { return MissionError{message, {}, 0, 0, {}}; }

quint32 crcOf(const QByteArray &data)
{
    return quint32(crc32(crc32(0, nullptr, 0), reinterpret_cast<const Bytef *>(data.constData()), uInt(data.size())));
}

// Raw deflate (no zlib header), as ZIP wants it.
std::optional<QByteArray> deflateRaw(const QByteArray &data)
{
    z_stream z{};
    if (deflateInit2(&z, Z_DEFAULT_COMPRESSION, Z_DEFLATED, -MAX_WBITS, 8, Z_DEFAULT_STRATEGY) != Z_OK)
        return std::nullopt;
    QByteArray out(int(deflateBound(&z, uLong(data.size()))), Qt::Uninitialized);
    z.next_in = reinterpret_cast<Bytef *>(const_cast<char *>(data.constData()));
    z.avail_in = uInt(data.size());
    z.next_out = reinterpret_cast<Bytef *>(out.data());
    z.avail_out = uInt(out.size());
    const int rc = deflate(&z, Z_FINISH);
    const auto written = z.total_out;
    deflateEnd(&z);
    if (rc != Z_STREAM_END)
        return std::nullopt;
    out.resize(qsizetype(written));
    return out;
}

std::optional<QByteArray> inflateRaw(const char *data, qint64 size, qint64 expected)
{
    z_stream z{};
    if (inflateInit2(&z, -MAX_WBITS) != Z_OK)
        return std::nullopt;
    QByteArray out(qsizetype(expected), Qt::Uninitialized);
    z.next_in = reinterpret_cast<Bytef *>(const_cast<char *>(data));
    z.avail_in = uInt(size);
    z.next_out = reinterpret_cast<Bytef *>(out.data());
    z.avail_out = uInt(out.size());
    const int rc = inflate(&z, Z_FINISH);
    const auto produced = z.total_out;
    inflateEnd(&z);
    if (rc != Z_STREAM_END || qint64(produced) != expected)
        return std::nullopt;
    return out;
}

struct Cursor
{
    const QByteArray &bytes;
    qint64 at;
    bool has(qint64 n) const { return at >= 0 && n >= 0 && at + n <= bytes.size(); }
    quint16 u16(qint64 offset) const { return qFromLittleEndian<quint16>(bytes.constData() + at + offset); }
    quint32 u32(qint64 offset) const { return qFromLittleEndian<quint32>(bytes.constData() + at + offset); }
};

} // namespace

Result<QByteArray> writeZip(const std::vector<ZipEntry> &entries)
{
    QByteArray out;
    QByteArray central;
    for (const ZipEntry &e : entries) {
        const QByteArray name = e.path.toUtf8();
        if (name.isEmpty() || name.size() > 0xffff)
            return zipError(QStringLiteral("a ZIP entry needs a name of 1 to 65535 bytes"));
        if (qint64(e.data.size()) >= std::numeric_limits<quint32>::max())
            return zipError(QStringLiteral("%1 is too large for a ZIP archive without ZIP64").arg(e.path));
        const quint32 crc = crcOf(e.data);
        const std::optional<QByteArray> deflated = deflateRaw(e.data);
        if (!deflated)
            return zipError(QStringLiteral("zlib could not compress %1").arg(e.path));
        const bool store = deflated->size() >= e.data.size();
        const QByteArray &payload = store ? e.data : *deflated;
        const quint32 offset = quint32(out.size());
        auto header = [&](QByteArray &to, bool centralEntry) {
            put32(to, centralEntry ? kCentralHeader : kLocalHeader);
            if (centralEntry)
                put16(to, kVersion);  // made by
            put16(to, kVersion);      // needed to extract
            put16(to, kUtf8Names);
            put16(to, store ? kStored : kDeflated);
            put16(to, kDosTime);
            put16(to, kDosDate);
            put32(to, crc);
            put32(to, quint32(payload.size()));
            put32(to, quint32(e.data.size()));
            put16(to, quint16(name.size()));
            put16(to, 0);  // extra field
            if (centralEntry) {
                put16(to, 0);  // comment
                put16(to, 0);  // disk
                put16(to, 0);  // internal attributes
                put32(to, 0100644u << 16);  // external: a regular file, rw-r--r--
                put32(to, offset);
            }
            to.append(name);
        };
        header(out, false);
        out.append(payload);
        header(central, true);
        if (qint64(out.size()) >= std::numeric_limits<quint32>::max())
            return zipError(QStringLiteral("the archive is too large for ZIP without ZIP64"));
    }
    if (entries.size() > 0xffff)
        return zipError(QStringLiteral("a ZIP archive without ZIP64 holds at most 65535 entries"));
    const quint32 centralOffset = quint32(out.size());
    out.append(central);
    put32(out, kEndOfCentralDirectory);
    put16(out, 0);
    put16(out, 0);
    put16(out, quint16(entries.size()));
    put16(out, quint16(entries.size()));
    put32(out, quint32(central.size()));
    put32(out, centralOffset);
    put16(out, 0);  // comment length
    return out;
}

Result<std::vector<ZipEntry>> readZip(const QByteArray &archive, qint64 maxEntryBytes)
{
    // The end-of-central-directory record is the last 22 bytes, unless a comment (up to 64 KiB) follows.
    qint64 eocd = -1;
    for (qint64 at = archive.size() - 22; at >= 0 && at >= archive.size() - 22 - 0xffff; --at) {
        if (Cursor{archive, at}.u32(0) == kEndOfCentralDirectory) {
            eocd = at;
            break;
        }
    }
    if (eocd < 0)
        return zipError(QStringLiteral("not a ZIP archive (no end of central directory record)"));
    const Cursor end{archive, eocd};
    const int count = end.u16(10);
    qint64 at = end.u32(16);
    std::vector<ZipEntry> entries;
    for (int i = 0; i < count; ++i) {
        const Cursor c{archive, at};
        if (!c.has(46) || c.u32(0) != kCentralHeader)
            return zipError(QStringLiteral("ZIP central directory entry %1 of %2 is damaged (at byte %3)").arg(i + 1).arg(count).arg(at));
        const quint16 flags = c.u16(8);
        const quint16 method = c.u16(10);
        const quint32 crc = c.u32(16);
        const qint64 packed = c.u32(20);
        const qint64 size = c.u32(24);
        const int nameLength = c.u16(28), extraLength = c.u16(30), commentLength = c.u16(32);
        const qint64 localAt = c.u32(42);
        if (!c.has(46 + nameLength))
            return zipError(QStringLiteral("ZIP central directory entry %1 is truncated").arg(i + 1));
        const QByteArray rawName = archive.mid(at + 46, nameLength);
        const QString name = (flags & kUtf8Names) ? QString::fromUtf8(rawName) : QString::fromLatin1(rawName);
        at += 46 + nameLength + extraLength + commentLength;
        if (name.endsWith(QLatin1Char('/')))
            continue;  // a directory
        if (flags & 1)
            return zipError(QStringLiteral("%1 is encrypted").arg(name));
        if (size > maxEntryBytes)
            return zipError(QStringLiteral("%1 is %2 bytes unpacked, more than the %3 allowed").arg(name).arg(size).arg(maxEntryBytes));
        const Cursor local{archive, localAt};
        if (!local.has(30) || local.u32(0) != kLocalHeader)
            return zipError(QStringLiteral("the local header of %1 is missing (at byte %2)").arg(name).arg(localAt));
        const qint64 dataAt = localAt + 30 + local.u16(26) + local.u16(28);
        if (!Cursor{archive, dataAt}.has(packed))
            return zipError(QStringLiteral("%1 is truncated: %2 bytes of data expected").arg(name).arg(packed));
        QByteArray data;
        if (method == kStored) {
            if (packed != size)
                return zipError(QStringLiteral("%1: stored size %2 differs from its size %3").arg(name).arg(packed).arg(size));
            data = archive.mid(dataAt, packed);
        } else if (method == kDeflated) {
            const auto inflated = inflateRaw(archive.constData() + dataAt, packed, size);
            if (!inflated)
                return zipError(QStringLiteral("%1 does not inflate to its %2 bytes (damaged)").arg(name).arg(size));
            data = *inflated;
        } else {
            return zipError(QStringLiteral("%1 uses compression method %2; only stored and deflated are read").arg(name).arg(method));
        }
        if (crcOf(data) != crc)
            return zipError(QStringLiteral("%1 fails its CRC-32 check (damaged)").arg(name));
        entries.push_back({name, std::move(data)});
    }
    return entries;
}

} // namespace sortie::mission::formats
