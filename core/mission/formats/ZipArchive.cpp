#include "ZipArchive.h"

#include <QtEndian>

#include <zip.h>

#include <algorithm>
#include <QCoreApplication>

namespace sortie::mission::formats {
namespace {

MissionError zipError(const QString &message) { return MissionError{message, {}, 0, 0, {}}; }

// libzip's words, or ours where its words would puzzle an operator.
QString libzipText(zip_error_t *error)
{
    switch (zip_error_code_zip(error)) {
    case ZIP_ER_EXISTS: return QCoreApplication::translate("ZipArchive", "two of its entries have the same name");
    case ZIP_ER_INCONS: return QCoreApplication::translate("ZipArchive", "its directory and its entries disagree");
    case ZIP_ER_NOZIP: return QCoreApplication::translate("ZipArchive", "it has no ZIP directory (truncated, or not a ZIP file)");
    default: return QString::fromUtf8(zip_error_strerror(error));
    }
}

// 1980-01-01 00:00 (the earliest MS-DOS date): archives do not change when nothing in them changed.
constexpr time_t kFixedTime = 315532800;

// One entry's extent in the archive as the central directory records it: its local header and the
// compressed body behind it (the local header's own name and extra lengths are read there).
struct Extent
{
    quint64 begin = 0, end = 0;
    QString name;
};

// Reads the central directory's local-header offsets, which libzip keeps to itself, to find entries
// that share bytes. libzip has parsed and checked this directory already (ZIP_CHECKCONS); this only
// walks its fixed-size records. ZIP64 offsets are refused: no KMZ is near 4 GiB.
Result<std::vector<Extent>> extentsOf(const QByteArray &archive)
{
    const auto u16 = [&](qsizetype at) { return qFromLittleEndian<quint16>(archive.constData() + at); };
    const auto u32 = [&](qsizetype at) { return qFromLittleEndian<quint32>(archive.constData() + at); };
    const qsizetype size = archive.size();
    // The end-of-central-directory record: 22 bytes and a comment of up to 65,535.
    qsizetype eocd = -1;
    for (qsizetype at = size - 22; at >= 0 && at >= size - 22 - 65535; --at) {
        if (u32(at) == 0x06054b50) {
            eocd = at;
            break;
        }
    }
    if (eocd < 0)
        return zipError(QCoreApplication::translate("ZipArchive", "the archive has no end of central directory"));
    const quint32 cdSize = u32(eocd + 12), cdOffset = u32(eocd + 16);
    if (cdOffset == 0xffffffffu || quint64(cdOffset) + cdSize > quint64(eocd))
        return zipError(QCoreApplication::translate("ZipArchive", "ZIP64 archives are not read"));
    std::vector<Extent> extents;
    for (qsizetype at = cdOffset; at + 46 <= qsizetype(cdOffset) + qsizetype(cdSize);) {
        if (u32(at) != 0x02014b50)
            return zipError(QCoreApplication::translate("ZipArchive", "a central directory record is damaged at byte %1").arg(at));
        const quint32 compressed = u32(at + 20), offset = u32(at + 42);
        const quint16 nameLength = u16(at + 28), extraLength = u16(at + 30), commentLength = u16(at + 32);
        if (compressed == 0xffffffffu || offset == 0xffffffffu)
            return zipError(QCoreApplication::translate("ZipArchive", "ZIP64 archives are not read"));
        if (quint64(offset) + 30 > quint64(size))
            return zipError(QCoreApplication::translate("ZipArchive", "an entry's local header lies outside the archive"));
        const quint64 localName = u16(qsizetype(offset) + 26), localExtra = u16(qsizetype(offset) + 28);
        extents.push_back({offset, offset + 30 + localName + localExtra + compressed,
                           QString::fromUtf8(archive.constData() + at + 46, qMin<qsizetype>(nameLength, size - at - 46))});
        at += 46 + nameLength + extraLength + commentLength;
    }
    return extents;
}

std::optional<MissionError> overlapping(std::vector<Extent> extents)
{
    std::sort(extents.begin(), extents.end(), [](const Extent &a, const Extent &b) { return a.begin < b.begin; });
    for (size_t i = 1; i < extents.size(); ++i) {
        if (extents[i].begin < extents[i - 1].end)
            return zipError(QCoreApplication::translate("ZipArchive", "the entries \"%1\" and \"%2\" share bytes in the archive (a ZIP bomb's trick): not read")
                                .arg(extents[i - 1].name, extents[i].name));
    }
    return std::nullopt;
}

} // namespace

struct ZipReader::State
{
    QByteArray bytes;  // libzip reads from here: it must outlive the archive
    zip_t *archive = nullptr;
    ZipLimits limits;
    qint64 inflated = 0;
    ~State()
    {
        if (archive)
            zip_discard(archive);
    }
};

ZipReader::ZipReader(std::unique_ptr<State> state) : m_state(std::move(state)) {}
ZipReader::ZipReader(ZipReader &&) noexcept = default;
ZipReader &ZipReader::operator=(ZipReader &&) noexcept = default;
ZipReader::~ZipReader() = default;

Result<ZipReader> ZipReader::open(const QByteArray &archive, ZipLimits limits)
{
    auto state = std::make_unique<State>();
    state->bytes = archive;
    state->limits = limits;
    zip_error_t error;
    zip_error_init(&error);
    zip_source_t *source = zip_source_buffer_create(state->bytes.constData(), zip_uint64_t(state->bytes.size()), 0, &error);
    if (!source) {
        const QString text = libzipText(&error);
        zip_error_fini(&error);
        return zipError(QCoreApplication::translate("ZipArchive", "not a ZIP archive: %1").arg(text));
    }
    state->archive = zip_open_from_source(source, ZIP_RDONLY | ZIP_CHECKCONS, &error);
    if (!state->archive) {
        zip_source_free(source);
        const QString text = libzipText(&error);
        zip_error_fini(&error);
        return zipError(QCoreApplication::translate("ZipArchive", "not a readable ZIP archive: %1").arg(text));
    }
    zip_error_fini(&error);
    const zip_int64_t count = zip_get_num_entries(state->archive, 0);
    if (count > limits.maxEntries)
        return zipError(QCoreApplication::translate("ZipArchive", "the archive lists %1 entries, more than the %2 read").arg(count).arg(limits.maxEntries));
    Result<std::vector<Extent>> extents = extentsOf(state->bytes);
    if (!extents)
        return extents.error();
    if (zip_int64_t(extents->size()) != count)
        return zipError(QCoreApplication::translate("ZipArchive", "the central directory lists %1 entries where libzip read %2").arg(extents->size()).arg(count));
    if (const auto overlap = overlapping(std::move(extents).value()))
        return *overlap;
    return ZipReader(std::move(state));
}

QStringList ZipReader::paths() const
{
    QStringList list;
    const zip_int64_t count = zip_get_num_entries(m_state->archive, 0);
    for (zip_int64_t i = 0; i < count; ++i) {
        const char *name = zip_get_name(m_state->archive, zip_uint64_t(i), ZIP_FL_ENC_GUESS);
        if (name && !QByteArray(name).endsWith('/'))
            list.append(QString::fromUtf8(name));
    }
    return list;
}

qint64 ZipReader::inflatedBytes() const
{
    return m_state->inflated;
}

Result<QByteArray> ZipReader::read(const QString &path)
{
    const ZipLimits &limits = m_state->limits;
    zip_stat_t stat;
    zip_stat_init(&stat);
    const QByteArray name = path.toUtf8();
    if (zip_stat(m_state->archive, name.constData(), ZIP_FL_ENC_GUESS, &stat) != 0)
        return zipError(QCoreApplication::translate("ZipArchive", "the archive has no \"%1\"").arg(path));
    const qint64 declared = qint64(stat.size);
    if (declared > limits.maxEntryBytes)
        return zipError(QCoreApplication::translate("ZipArchive", "\"%1\" would inflate to %2 bytes, more than the %3 read from one entry")
                            .arg(path).arg(declared).arg(limits.maxEntryBytes));
    if (m_state->inflated + declared > limits.maxTotalBytes)
        return zipError(QCoreApplication::translate("ZipArchive", "reading \"%1\" would inflate the archive past %2 bytes in all").arg(path).arg(limits.maxTotalBytes));
    if (declared > limits.ratioFloorBytes && double(declared) > limits.maxRatio * double(qMax<zip_uint64_t>(stat.comp_size, 1)))
        return zipError(QCoreApplication::translate("ZipArchive", "\"%1\" claims %2 bytes from %3 compressed, more than %4 times: not inflated")
                            .arg(path).arg(declared).arg(stat.comp_size).arg(limits.maxRatio));
    zip_file_t *file = zip_fopen_index(m_state->archive, stat.index, 0);
    if (!file)
        return zipError(QCoreApplication::translate("ZipArchive", "\"%1\" cannot be read: %2").arg(path, libzipText(zip_get_error(m_state->archive))));
    // Never more than the declared size: libzip stops there and checks the CRC at the end.
    QByteArray data(declared, Qt::Uninitialized);
    qint64 filled = 0;
    while (filled < declared) {
        const zip_int64_t n = zip_fread(file, data.data() + filled, zip_uint64_t(declared - filled));
        if (n < 0) {
            const QString text = libzipText(zip_file_get_error(file));
            zip_fclose(file);
            return zipError(QCoreApplication::translate("ZipArchive", "\"%1\" is damaged: %2").arg(path, text));
        }
        if (n == 0)
            break;
        filled += n;
    }
    char extra;
    const bool longer = zip_fread(file, &extra, 1) > 0;
    const int closed = zip_fclose(file);
    if (filled != declared || longer)
        return zipError(QCoreApplication::translate("ZipArchive", "\"%1\" holds a different size than the archive says (%2 bytes)").arg(path).arg(declared));
    if (closed != 0)
        return zipError(QCoreApplication::translate("ZipArchive", "\"%1\" is damaged (its CRC does not match)").arg(path));
    m_state->inflated += declared;
    return data;
}

Result<std::vector<ZipEntry>> readZip(const QByteArray &archive, ZipLimits limits)
{
    Result<ZipReader> opened = ZipReader::open(archive, limits);
    if (!opened)
        return opened.error();
    ZipReader reader = std::move(opened).value();
    std::vector<ZipEntry> entries;
    for (const QString &path : reader.paths()) {
        Result<QByteArray> data = reader.read(path);
        if (!data)
            return data.error();
        entries.push_back({path, std::move(data).value()});
    }
    return entries;
}

Result<QByteArray> writeZip(const std::vector<ZipEntry> &entries)
{
    zip_error_t error;
    zip_error_init(&error);
    zip_source_t *buffer = zip_source_buffer_create(nullptr, 0, 0, &error);
    zip_t *archive = buffer ? zip_open_from_source(buffer, ZIP_TRUNCATE, &error) : nullptr;
    const auto fail = [&](const QString &what) {
        const QString text = what + QStringLiteral(": ") + libzipText(archive ? zip_get_error(archive) : &error);
        if (archive)
            zip_discard(archive);
        else if (buffer)
            zip_source_free(buffer);
        zip_error_fini(&error);
        return zipError(QCoreApplication::translate("ZipArchive", "the archive could not be written: %1").arg(text));
    };
    if (!archive)
        return fail(QStringLiteral("opening"));
    zip_source_keep(buffer);  // its bytes are the result, read after the archive is closed
    for (const ZipEntry &entry : entries) {
        // libzip copies nothing here: the entries outlive zip_close, which reads them.
        zip_source_t *data = zip_source_buffer(archive, entry.data.constData(), zip_uint64_t(entry.data.size()), 0);
        const QByteArray name = entry.path.toUtf8();
        const zip_int64_t index = data ? zip_file_add(archive, name.constData(), data, ZIP_FL_ENC_UTF_8) : -1;
        if (index < 0) {
            if (data)
                zip_source_free(data);
            zip_source_free(buffer);
            return fail(entry.path);
        }
        zip_set_file_compression(archive, zip_uint64_t(index), ZIP_CM_DEFLATE, 0);
        zip_file_set_mtime(archive, zip_uint64_t(index), kFixedTime, 0);
    }
    if (zip_close(archive) != 0) {
        const QString text = libzipText(zip_get_error(archive));
        zip_discard(archive);
        zip_source_free(buffer);
        zip_error_fini(&error);
        return zipError(QCoreApplication::translate("ZipArchive", "the archive could not be written: %1").arg(text));
    }
    QByteArray out;
    zip_stat_t stat;
    if (zip_source_stat(buffer, &stat) == 0 && zip_source_open(buffer) == 0) {
        out.resize(qsizetype(stat.size));
        const zip_int64_t n = zip_source_read(buffer, out.data(), stat.size);
        zip_source_close(buffer);
        if (n != zip_int64_t(stat.size))
            out.clear();
    }
    zip_source_free(buffer);
    zip_error_fini(&error);
    if (out.isEmpty())
        return zipError(QCoreApplication::translate("ZipArchive", "the archive could not be written: its bytes could not be read back"));
    return out;
}

} // namespace sortie::mission::formats
