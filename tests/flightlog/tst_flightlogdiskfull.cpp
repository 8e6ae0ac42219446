// FlightLogWriter on a filesystem that fills up and frees again: a small tmpfs the test mounts
// (it must run as root, or with CAP_SYS_ADMIN; when it cannot mount, it fails and says why). A
// chunk whose commit fails is kept and written once there is room again, a vehicle first named in
// it included, and the log reads back whole: no block names a vehicle that is not there.
#include "FlightLog.h"
#include "FlightLogWriter.h"

#include <QDir>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <cerrno>
#include <cstring>
#include <sys/mount.h>

using namespace sortie;
using flightlog::FlightLog;
using flightlog::FlightLogWriter;
using flightlog::RecordingChunk;
using vehicle::TelemetryField;

namespace {

constexpr int64_t kT0 = 1'790'000'000'000; // ms

// `count` samples of latitude and altitude for `key`, 10 Hz from `from`, with noise that does not
// compress: each chunk needs pages of its own.
flightlog::RecordedSamples samples(const QString &key, int64_t from, int count, quint32 seed)
{
    flightlog::RecordedSamples s;
    s.vehicleKey = key;
    flightlog::FieldSamples lat{TelemetryField::Latitude, {}}, alt{TelemetryField::AltitudeAmsl, {}};
    for (int i = 0; i < count; ++i) {
        seed = seed * 1664525u + 1013904223u;
        const int64_t t = from + int64_t(i) * 100;
        lat.samples.push_back({t, 56.97 + double(seed % 100000) * 1e-7});
        alt.samples.push_back({t, 40.0 + double((seed >> 8) % 5000) * 0.01});
    }
    s.fields = {std::move(lat), std::move(alt)};
    return s;
}

flightlog::RecordedVehicle vehicleNamed(const QString &key, const QString &name)
{
    flightlog::RecordedVehicle v{key, {}};
    v.identity.id = key.section(QLatin1Char(':'), 1);
    v.identity.name = name;
    v.identity.protocol = QStringLiteral("VCI");
    return v;
}

uint64_t samplesOf(const FlightLog &log, const QString &key)
{
    const int index = log.vehicleIndex(key);
    return index < 0 ? 0 : log.vehicles()[size_t(index)].sampleCount();
}

} // namespace

class TestFlightLogDiskFull : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    QString m_mount;
    bool m_mounted = false;

    // Fills the filesystem to the last byte; returns the filler's path.
    QString fill()
    {
        const QString path = QDir(m_mount).filePath(QStringLiteral("filler"));
        QFile filler(path);
        if (!filler.open(QIODevice::WriteOnly))
            return {};
        const QByteArray block(4096, 'x');
        while (filler.write(block) == block.size() && filler.flush()) {
        }
        // The last partial page too.
        while (filler.write("x", 1) == 1 && filler.flush()) {
        }
        return path;
    }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_mount = m_dir.filePath(QStringLiteral("small"));
        QVERIFY(QDir().mkpath(m_mount));
        if (::mount("tmpfs", QFile::encodeName(m_mount).constData(), "tmpfs", 0, "size=1m,mode=0700") != 0)
            QFAIL(qPrintable(QStringLiteral("cannot mount a 1 MiB tmpfs at %1: %2 (this test needs root or CAP_SYS_ADMIN)")
                                 .arg(m_mount, QString::fromLocal8Bit(std::strerror(errno)))));
        m_mounted = true;
    }

    void cleanupTestCase()
    {
        if (m_mounted)
            ::umount2(QFile::encodeName(m_mount).constData(), MNT_DETACH);
    }

    void aChunkThatFailsIsWrittenOnceThereIsRoom()
    {
        const QString path = QDir(m_mount).filePath(QStringLiteral("flight.sortielog"));
        FlightLogWriter writer(path, {0, 0});
        QString error;
        QVERIFY2(writer.open(&error), qPrintable(error));
        QSignalSpy errors(&writer, &FlightLogWriter::errorOccurred);

        RecordingChunk first;
        first.vehicles = {vehicleNamed(QStringLiteral("VCI:a"), QStringLiteral("Alpha"))};
        first.samples = {samples(QStringLiteral("VCI:a"), kT0, 50, 1)};
        writer.write(first);
        QCOMPARE(writer.unwrittenChunks(), 0);
        QCOMPARE(errors.count(), 0);

        const QString filler = fill();
        QVERIFY(!filler.isEmpty());

        // The disk is full: a new vehicle, named first in a chunk that cannot be committed.
        RecordingChunk second;
        second.vehicles = {vehicleNamed(QStringLiteral("VCI:b"), QStringLiteral("Bravo"))};
        second.samples = {samples(QStringLiteral("VCI:a"), kT0 + 5'000, 2000, 2), samples(QStringLiteral("VCI:b"), kT0 + 5'000, 2000, 3)};
        writer.write(second);
        QCOMPARE(writer.unwrittenChunks(), 1);
        QCOMPARE(errors.count(), 1);
        QVERIFY2(errors.last().at(0).toString().contains(QStringLiteral("full"), Qt::CaseInsensitive), qPrintable(errors.last().at(0).toString()));

        RecordingChunk third;
        third.samples = {samples(QStringLiteral("VCI:a"), kT0 + 205'000, 500, 4), samples(QStringLiteral("VCI:b"), kT0 + 205'000, 500, 5)};
        third.events = {{QStringLiteral("VCI:b"), kT0 + 205'000, QStringLiteral("armed"), QStringLiteral("Armed"), -1}};
        writer.write(third);
        QCOMPARE(writer.unwrittenChunks(), 2);
        QCOMPARE(errors.count(), 1); // said once

        // Room again: what failed goes first, then the new chunk.
        QVERIFY(QFile::remove(filler));
        RecordingChunk fourth;
        fourth.samples = {samples(QStringLiteral("VCI:a"), kT0 + 255'000, 100, 6), samples(QStringLiteral("VCI:b"), kT0 + 255'000, 100, 7)};
        writer.write(fourth);
        QCOMPARE(writer.unwrittenChunks(), 0);
        QCOMPARE(errors.count(), 2);
        QVERIFY(errors.last().at(0).toString().isEmpty()); // the error is over
        QCOMPARE(writer.stats().values, quint64(2 * (50 + 2000 + 2000 + 500 + 500 + 100 + 100)));
        writer.close();

        const auto log = FlightLog::open(path, &error);
        QVERIFY2(log, qPrintable(error));
        QVERIFY2(log->damage().isEmpty(), qPrintable(log->damage()));
        QCOMPARE(log->vehicles().size(), size_t(2));
        QCOMPARE(samplesOf(*log, QStringLiteral("VCI:a")), uint64_t(2 * (50 + 2000 + 500 + 100)));
        QCOMPARE(samplesOf(*log, QStringLiteral("VCI:b")), uint64_t(2 * (2000 + 500 + 100)));
        QCOMPARE(log->vehicles()[size_t(log->vehicleIndex(QStringLiteral("VCI:b")))].name(), QStringLiteral("Bravo"));
        QCOMPARE(log->events().size(), size_t(1));
        QCOMPARE(log->end(), kT0 + 255'000 + 99 * 100);
        QFile::remove(path);
    }
};

QTEST_GUILESS_MAIN(TestFlightLogDiskFull)
#include "tst_flightlogdiskfull.moc"
