// Archives from outside are hostile until read. Built here byte by byte: entries that share bytes
// (one nested inside another; several names for one body), an entry that claims a thousand times
// its compressed size, a truncated central directory, an archive past its total budget. Each is
// refused with what is wrong, before it is inflated; and the bomb that once took half a gigabyte
// (eight names for 64 MiB of deflated zeros) costs `sortie-plan stats` a bounded resident size.
#include "WpmlFormat.h"
#include "ZipArchive.h"

#include <QTemporaryFile>
#include <QTemporaryDir>
#include <QTest>
#include <QtEndian>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <zlib.h>

using namespace sortie::mission::formats;

namespace {

void put16(QByteArray &out, quint16 v) { char b[2]; qToLittleEndian(v, b); out.append(b, 2); }
void put32(QByteArray &out, quint32 v) { char b[4]; qToLittleEndian(v, b); out.append(b, 4); }
quint32 crcOf(const QByteArray &d) { return quint32(crc32(0, reinterpret_cast<const Bytef *>(d.constData()), uInt(d.size()))); }

// A stored (uncompressed) entry's local header and body, per PKWARE's APPNOTE 4.3.7.
QByteArray localRecord(const QByteArray &name, const QByteArray &body)
{
    QByteArray out;
    put32(out, 0x04034b50); put16(out, 20); put16(out, 0); put16(out, 0); put16(out, 0); put16(out, 0x21);
    put32(out, crcOf(body)); put32(out, quint32(body.size())); put32(out, quint32(body.size()));
    put16(out, quint16(name.size())); put16(out, 0);
    return out + name + body;
}

// A central directory record (APPNOTE 4.3.12) for a stored entry at `offset`.
QByteArray centralRecord(const QByteArray &name, const QByteArray &body, quint32 offset, quint16 method = 0, quint32 compressed = 0)
{
    QByteArray out;
    put32(out, 0x02014b50); put16(out, 20); put16(out, 20); put16(out, 0); put16(out, method); put16(out, 0); put16(out, 0x21);
    put32(out, crcOf(body)); put32(out, method ? compressed : quint32(body.size())); put32(out, quint32(body.size()));
    put16(out, quint16(name.size())); put16(out, 0); put16(out, 0); put16(out, 0); put16(out, 0); put32(out, 0); put32(out, offset);
    return out + name;
}

// `size` zeros deflated, in 1 MiB steps so the test itself never holds them: a local header with
// its deflated body, and the central record that matches it.
std::pair<QByteArray, QByteArray> deflatedZeros(const QByteArray &name, qint64 size)
{
    const QByteArray chunk(1024 * 1024, '\0');
    z_stream z{};
    deflateInit2(&z, Z_BEST_COMPRESSION, Z_DEFLATED, -MAX_WBITS, 8, Z_DEFAULT_STRATEGY);
    QByteArray body;
    char out[16384];
    uLong crc = crc32(0, nullptr, 0);
    for (qint64 left = size; left > 0 || z.avail_in > 0;) {
        const bool last = left <= chunk.size();
        z.next_in = reinterpret_cast<Bytef *>(const_cast<char *>(chunk.constData()));
        z.avail_in = uInt(qMin<qint64>(left, chunk.size()));
        crc = crc32(crc, z.next_in, z.avail_in);
        left -= z.avail_in;
        int rc;
        do {
            z.next_out = reinterpret_cast<Bytef *>(out);
            z.avail_out = sizeof out;
            rc = deflate(&z, last ? Z_FINISH : Z_NO_FLUSH);
            body.append(out, qsizetype(sizeof out - z.avail_out));
        } while (z.avail_out == 0 || (last && rc != Z_STREAM_END));
        if (last)
            break;
    }
    deflateEnd(&z);
    QByteArray local;
    put32(local, 0x04034b50); put16(local, 20); put16(local, 0); put16(local, 8); put16(local, 0); put16(local, 0x21);
    put32(local, quint32(crc)); put32(local, quint32(body.size())); put32(local, quint32(size));
    put16(local, quint16(name.size())); put16(local, 0);
    QByteArray central;
    put32(central, 0x02014b50); put16(central, 20); put16(central, 20); put16(central, 0); put16(central, 8); put16(central, 0); put16(central, 0x21);
    put32(central, quint32(crc)); put32(central, quint32(body.size())); put32(central, quint32(size));
    put16(central, quint16(name.size())); put16(central, 0); put16(central, 0); put16(central, 0); put16(central, 0); put32(central, 0); put32(central, 0);
    return {local + name + body, central + name};
}

// sortie-plan's exit code, standard error and peak resident size (its own, through wait4).
struct Peak
{
    int exitCode = -1;
    QString err;
    double mib = 0;
};
Peak runMeasured(const QStringList &arguments)
{
    QTemporaryFile errors;
    if (!errors.open())
        return {};
    std::vector<QByteArray> args{QByteArray(SORTIE_PLAN_BIN)};
    for (const QString &a : arguments)
        args.push_back(a.toLocal8Bit());
    std::vector<char *> argv;
    for (QByteArray &a : args)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    const pid_t pid = fork();
    if (pid == 0) {
        dup2(errors.handle(), 2);
        execv(argv[0], argv.data());
        _exit(127);
    }
    int status = 0;
    rusage usage{};
    if (pid < 0 || wait4(pid, &status, 0, &usage) != pid)
        return {};
    errors.seek(0);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, QString::fromUtf8(errors.readAll()), double(usage.ru_maxrss) / 1024.0};
}

QByteArray endRecord(int entries, qsizetype cdSize, qsizetype cdOffset)
{
    QByteArray out;
    put32(out, 0x06054b50); put16(out, 0); put16(out, 0); put16(out, quint16(entries)); put16(out, quint16(entries));
    put32(out, quint32(cdSize)); put32(out, quint32(cdOffset)); put16(out, 0);
    return out;
}

} // namespace

class TestZipArchive : public QObject
{
    Q_OBJECT

private slots:
    // The case end to end: 64 MiB of zeros, deflated once, named eight times.
    void theBombCostsBoundedMemory()
    {
        const auto [local, central] = deflatedZeros("wpmz/waylines.wpml", 64 * 1024 * 1024);
        QByteArray cd;
        for (int i = 0; i < 8; ++i)
            cd += central;
        const QByteArray bomb = local + cd + endRecord(8, cd.size(), local.size());
        QVERIFY(bomb.size() < 200 * 1024);
        QTemporaryDir dir;
        QFile f(dir.filePath(QStringLiteral("bomb.kmz")));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(bomb);
        f.close();

        // The same program on a small valid route is the baseline: what it takes to start (more
        // under ASan), and the pages it shares with this process at the fork.
        QFile route(dir.filePath(QStringLiteral("small.kmz")));
        QVERIFY(route.open(QIODevice::WriteOnly));
        route.write(writeZip({{QStringLiteral("wpmz/waylines.wpml"), QByteArray("<kml/>")}}).value());
        route.close();
        const Peak baseline = runMeasured({QStringLiteral("stats"), route.fileName()});
        const Peak bombed = runMeasured({QStringLiteral("stats"), f.fileName()});
        QVERIFY(bombed.exitCode != 0);
        QVERIFY2(bombed.err.contains(QStringLiteral("bomb.kmz")) && bombed.err.contains(QStringLiteral("same name")), qPrintable(bombed.err));
        qInfo("sortie-plan stats: peak resident %.1f MiB on the bomb, %.1f MiB on a small route", bombed.mib, baseline.mib);
        QVERIFY2(bombed.mib < baseline.mib + 16, qPrintable(QString::number(bombed.mib)));  // it once reached 544 MiB
    }

    void writesAndReadsBack()
    {
        const std::vector<ZipEntry> entries{{QStringLiteral("wpmz/template.kml"), QByteArray("<kml/>")},
                                            {QStringLiteral("wpmz/waylines.wpml"), QByteArray(5000, 'x')}};
        const auto zip = writeZip(entries);
        QVERIFY2(zip.ok(), qPrintable(zip.ok() ? QString() : zip.error().message));
        QVERIFY(zip->size() < 1000);  // deflated
        QCOMPARE(writeZip(entries).value(), zip.value());  // deterministic
        auto opened = ZipReader::open(zip.value());
        QVERIFY(opened.ok());
        ZipReader reader = std::move(opened).value();
        QCOMPARE(reader.paths(), (QStringList{"wpmz/template.kml", "wpmz/waylines.wpml"}));
        QCOMPARE(reader.read(QStringLiteral("wpmz/waylines.wpml")).value(), entries[1].data);
        QCOMPARE(reader.inflatedBytes(), 5000);
        QVERIFY(!reader.read(QStringLiteral("wpmz/missing")).ok());
    }

    // Entry B's local header and body lie inside entry A's stored body: each entry is consistent
    // on its own (libzip accepts it), but reading both reads B's bytes twice.
    void refusesAnEntryNestedInAnother()
    {
        const QByteArray inner = localRecord("b.txt", QByteArray(100, 'z'));
        const QByteArray outer = localRecord("a.txt", inner);
        const qsizetype innerOffset = outer.size() - inner.size();
        QByteArray cd = centralRecord("a.txt", inner, 0) + centralRecord("b.txt", QByteArray(100, 'z'), quint32(innerOffset));
        const QByteArray zip = outer + cd + endRecord(2, cd.size(), outer.size());
        const auto reader = ZipReader::open(zip);
        QVERIFY(!reader.ok());
        QVERIFY2(reader.error().message.contains(QStringLiteral("share bytes")), qPrintable(reader.error().message));
    }

    // The bomb: several central records for one deflated body of zeros.
    void refusesSeveralNamesForOneBody()
    {
        const QByteArray zeros(8 * 1024 * 1024, '\0');
        const QByteArray one = writeZip({{QStringLiteral("wpmz/waylines.wpml"), zeros}}).value();
        const qsizetype cdOffset = qFromLittleEndian<quint32>(one.constData() + one.size() - 6);
        const QByteArray body = one.left(cdOffset);
        const QByteArray record = one.mid(cdOffset, one.size() - 22 - cdOffset);
        QByteArray cd;
        for (int i = 0; i < 8; ++i)
            cd += record;
        const QByteArray zip = body + cd + endRecord(8, cd.size(), body.size());
        const auto reader = ZipReader::open(zip);
        QVERIFY(!reader.ok());
        QVERIFY2(!reader.error().message.isEmpty(), "a reason");
        const auto wpml = readWpml(zip);
        QVERIFY(!wpml.ok());
    }

    void refusesAnEntryThatClaimsTooMuchPerByte()
    {
        const QByteArray zip = writeZip({{QStringLiteral("wpmz/waylines.wpml"), QByteArray(16 * 1024 * 1024, '\0')}}).value();
        auto opened = ZipReader::open(zip);
        QVERIFY(opened.ok());
        ZipReader reader = std::move(opened).value();
        const auto data = reader.read(QStringLiteral("wpmz/waylines.wpml"));
        QVERIFY(!data.ok());
        QVERIFY2(data.error().message.contains(QStringLiteral("more than 200 times")), qPrintable(data.error().message));
        QCOMPARE(reader.inflatedBytes(), 0);  // refused before inflating
        const auto wpml = readWpml(zip);
        QVERIFY(!wpml.ok());
        QVERIFY2(wpml.error().message.contains(QStringLiteral("waylines.wpml")), qPrintable(wpml.error().message));
    }

    void refusesPastTheTotalBudget()
    {
        const QByteArray zip = writeZip({{QStringLiteral("a"), QByteArray(3000, 'a')}, {QStringLiteral("b"), QByteArray(3000, 'b')}}).value();
        ZipLimits limits;
        limits.maxTotalBytes = 5000;
        auto opened = ZipReader::open(zip, limits);
        QVERIFY(opened.ok());
        ZipReader reader = std::move(opened).value();
        QVERIFY(reader.read(QStringLiteral("a")).ok());
        const auto second = reader.read(QStringLiteral("b"));
        QVERIFY(!second.ok());
        QVERIFY2(second.error().message.contains(QStringLiteral("5000 bytes in all")), qPrintable(second.error().message));
        QVERIFY(!readZip(zip, limits).ok());
    }

    void refusesATruncatedCentralDirectory()
    {
        const QByteArray zip = writeZip({{QStringLiteral("wpmz/waylines.wpml"), QByteArray("<kml/>")}}).value();
        for (int cut : {10, 30, 60}) {
            const auto reader = ZipReader::open(zip.left(zip.size() - cut));
            QVERIFY2(!reader.ok(), qPrintable(QString::number(cut)));
            QVERIFY(!reader.error().message.isEmpty());
        }
        const auto wpml = readWpml(QByteArray("PK\x03\x04 and then nothing"));
        QVERIFY(!wpml.ok());
    }

};

QTEST_GUILESS_MAIN(TestZipArchive)
#include "tst_ziparchive.moc"
