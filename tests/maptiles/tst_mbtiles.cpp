// The MBTiles file: created with the specification's tables, tiles stored in TMS rows and read back
// in XYZ, replaced not duplicated, metadata read leniently with every unreadable value named, and
// a file that is not MBTiles refused with its name. Writes the metadata fuzz target's seeds when
// SORTIE_WRITE_FUZZ_SEEDS is set (tests/fuzz/mbtiles_metadata-corpus).
#include "MbTilesFile.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QScopeGuard>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QTest>

#include <sys/stat.h>

using namespace sortie::maptiles;

namespace {
// The fuzz target's input: one metadata row a line, name and value split at the first tab.
const QList<QPair<QString, QByteArray>> kSeeds{
    {QStringLiteral("complete.txt"), "name\tRiga\nattribution\t(c) Test contributors\nformat\tpng\nminzoom\t10\nmaxzoom\t16\n"
                                     "bounds\t23.95,56.9,24.2,57.0\ntype\tbaselayer\ndescription\tTaken offline\n"},
    {QStringLiteral("bad-values.txt"), "minzoom\tten\nmaxzoom\t99\nbounds\t1,2,3\nformat\t\n"},
    {QStringLiteral("swapped-zooms.txt"), "minzoom\t14\nmaxzoom\t3\nbounds\t24.2,57.0,23.95,56.9\n"},
    {QStringLiteral("empty.txt"), ""},
};

QList<QPair<QString, QString>> pairsOf(const QByteArray &input)
{
    QList<QPair<QString, QString>> pairs;
    for (const QByteArray &line : input.split('\n')) {
        const qsizetype tab = line.indexOf('\t');
        if (tab >= 0)
            pairs.append({QString::fromUtf8(line.left(tab)), QString::fromUtf8(line.mid(tab + 1))});
    }
    return pairs;
}
} // namespace

class TestMbTiles : public QObject
{
    Q_OBJECT

private slots:
    void writesAndReadsTilesInTmsRows()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("sub/area.mbtiles"));
        QString error;
        {
            MbTilesFile file;
            QVERIFY2(file.open(path, MbTilesFile::Mode::ReadWrite, &error), qPrintable(error));
            QVERIFY2(file.writeTiles({{{1, 0, 0}, "north-west"}, {{1, 1, 1}, "south-east"}, {{3, 5, 2}, "three"}}, &error), qPrintable(error));
            QVERIFY(file.writeTiles({{{1, 0, 0}, "replaced"}}, &error));
            QCOMPARE(file.tileCount(), 3);
            QCOMPARE(file.tile({1, 0, 0}).value(), QByteArray("replaced"));
            QVERIFY(!file.tile({1, 1, 0}));
            QCOMPARE(file.storedTiles(1, 1), (QSet<quint64>{TileId{1, 0, 0}.packed(), TileId{1, 1, 1}.packed()}));
            QCOMPARE(file.storedZoomRange().value(), std::pair(1, 3));
            QCOMPARE(file.integrityCheck(), QStringLiteral("ok"));
        }
        // What another MBTiles reader sees: XYZ 1/0/0 (north-west) is TMS row 1.
        {
            QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), QStringLiteral("check"));
            db.setDatabaseName(path);
            QVERIFY(db.open());
            QSqlQuery q(db);
            QVERIFY(q.exec(QStringLiteral("SELECT tile_data FROM tiles WHERE zoom_level = 1 AND tile_column = 0 AND tile_row = 1")));
            QVERIFY(q.next());
            QCOMPARE(q.value(0).toByteArray(), QByteArray("replaced"));
            q.finish();
            db.close();
        }
        QSqlDatabase::removeDatabase(QStringLiteral("check"));
        MbTilesFile reader;
        QVERIFY(reader.open(path, MbTilesFile::Mode::ReadOnly, &error));
        QCOMPARE(reader.tile({3, 5, 2}).value(), QByteArray("three"));
        QCOMPARE(reader.meanTileBytes().value(), (8.0 + 10 + 5) / 3);
        QVERIFY(!reader.writeTiles({{{0, 0, 0}, "x"}}, &error)); // read-only
        QVERIFY(!error.isEmpty());
    }

    // Issue 36: packs took the umask. A pack is the operator's: 0600, its new folder 0700.
    void packsArePrivate()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("new/area.mbtiles"));
        const mode_t before = ::umask(022);
        const auto restore = qScopeGuard([before] { ::umask(before); });
        QString error;
        MbTilesFile file;
        QVERIFY2(file.open(path, MbTilesFile::Mode::ReadWrite, &error), qPrintable(error));
        QVERIFY2(file.writeTiles({{{1, 0, 0}, "tile"}}, &error), qPrintable(error));
        const auto others = QFileDevice::ReadGroup | QFileDevice::WriteGroup | QFileDevice::ExeGroup | QFileDevice::ReadOther
                          | QFileDevice::WriteOther | QFileDevice::ExeOther;
        QCOMPARE(QFileInfo(path).permissions() & others, QFileDevice::Permissions());
        QCOMPARE(QFileInfo(QFileInfo(path).path()).permissions() & others, QFileDevice::Permissions());
        for (const char *journal : {"-journal", "-wal", "-shm"})
            if (QFileInfo::exists(path + QLatin1String(journal)))
                QCOMPARE(QFileInfo(path + QLatin1String(journal)).permissions() & others, QFileDevice::Permissions());
    }

    void metadataRoundTrip()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("meta.mbtiles"));
        MbTilesFile file;
        QString error;
        QVERIFY(file.open(path, MbTilesFile::Mode::ReadWrite, &error));
        MbTilesMetadata meta = MbTilesMetadata::fromPairs(pairsOf(kSeeds[0].second));
        QVERIFY2(meta.problems.isEmpty(), qPrintable(meta.problems.join(QLatin1Char('\n'))));
        QCOMPARE(meta.name, QStringLiteral("Riga"));
        QCOMPARE(meta.minZoom.value(), 10);
        QCOMPARE(meta.bounds->west, 23.95);
        QCOMPARE(meta.bounds->north, 57.0);
        QCOMPARE(meta.others.size(), 1);
        QVERIFY(file.writeMetadata(meta, &error));
        const MbTilesMetadata back = file.metadata();
        QCOMPARE(back.attribution, meta.attribution);
        QCOMPARE(back.maxZoom, meta.maxZoom);
        QCOMPARE(back.format, QStringLiteral("png"));
        QCOMPARE(back.others, meta.others);
    }

    void badMetadataIsNamedAndLeftMissing()
    {
        const MbTilesMetadata bad = MbTilesMetadata::fromPairs(pairsOf(kSeeds[1].second));
        QVERIFY(!bad.minZoom && !bad.maxZoom && !bad.bounds);
        QCOMPARE(bad.problems.size(), 3);
        QVERIFY2(bad.problems.at(0).startsWith(QStringLiteral("minzoom: 'ten'")), qPrintable(bad.problems.at(0)));
        QVERIFY(bad.problems.at(1).startsWith(QStringLiteral("maxzoom: '99'")));
        QVERIFY(bad.problems.at(2).startsWith(QStringLiteral("bounds:")));
        const MbTilesMetadata swapped = MbTilesMetadata::fromPairs(pairsOf(kSeeds[2].second));
        QVERIFY(!swapped.minZoom && !swapped.maxZoom && !swapped.bounds);
        QCOMPARE(swapped.problems.size(), 2);
        QVERIFY(swapped.problems.at(1).contains(QStringLiteral("above maxzoom")));
    }

    void notMbTilesIsRefused()
    {
        QTemporaryDir dir;
        MbTilesFile file;
        QString error;
        QVERIFY(!file.open(dir.filePath(QStringLiteral("absent.mbtiles")), MbTilesFile::Mode::ReadOnly, &error));
        QVERIFY(error.contains(QStringLiteral("does not exist")));
        const QString text = dir.filePath(QStringLiteral("notes.mbtiles"));
        QFile notes(text);
        QVERIFY(notes.open(QIODevice::WriteOnly));
        notes.write("these are not tiles, and long enough to not be an empty database\n");
        notes.close();
        for (const auto mode : {MbTilesFile::Mode::ReadOnly, MbTilesFile::Mode::ReadWrite}) {
            error.clear();
            QVERIFY(!file.open(text, mode, &error));
            QVERIFY2(error.contains(text), qPrintable(error));
        }
        QFile check(text);
        QVERIFY(check.open(QIODevice::ReadOnly));
        QVERIFY(check.readAll().startsWith("these are not tiles")); // nothing lost
    }

    void fuzzSeeds()
    {
        const QDir corpus(QStringLiteral(SORTIE_FUZZ_DIR "/mbtiles_metadata-corpus"));
        const bool write = qEnvironmentVariableIsSet("SORTIE_WRITE_FUZZ_SEEDS");
        if (write)
            QVERIFY(QDir().mkpath(corpus.path()));
        for (const auto &[name, bytes] : kSeeds) {
            QFile file(corpus.filePath(name));
            if (write) {
                QVERIFY(file.open(QIODevice::WriteOnly));
                file.write(bytes);
                continue;
            }
            QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(file.fileName()));
            QCOMPARE(file.readAll(), bytes); // the committed seeds are this test's
        }
    }
};

QTEST_GUILESS_MAIN(TestMbTiles)
#include "tst_mbtiles.moc"
