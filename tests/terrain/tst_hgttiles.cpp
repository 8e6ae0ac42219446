// The SRTM tile reader: names, both resolutions, bilinear heights, voids, tile edges, bad files.
#include "HgtTile.h"
#include "HgtTileSource.h"
#include "HgtWriter.h"

#include <QTemporaryDir>
#include <QTest>

using namespace sortie::terrain;
using namespace sortie::terrain::test;

class TstHgtTiles : public QObject
{
    Q_OBJECT

private slots:
    void names()
    {
        QCOMPARE(parseHgtName(QStringLiteral("N56E024.hgt")), (TileCell{56, 24}));
        QCOMPARE(parseHgtName(QStringLiteral("s03w071.HGT")), (TileCell{-3, -71}));
        QVERIFY(!parseHgtName(QStringLiteral("N56E24.hgt")));
        QVERIFY(!parseHgtName(QStringLiteral("N95E024.hgt")));
        QVERIFY(!parseHgtName(QStringLiteral("N56E024.tif")));
        QCOMPARE(hgtName({-3, -71}), QStringLiteral("S03W071.hgt"));
        QCOMPARE(TileCell::containing(56.5, 24.2), (TileCell{56, 24}));
        QCOMPARE(TileCell::containing(-0.5, -0.5), (TileCell{-1, -1}));
    }

    // A tilted plane: bilinear interpolation reproduces it exactly, at both resolutions.
    void plane_data() { QTest::addColumn<int>("size"); QTest::newRow("3 arc-second") << 1201; QTest::newRow("1 arc-second") << 3601; }
    void plane()
    {
        QFETCH(int, size);
        QTemporaryDir dir;
        QVERIFY(writeHgt(dir.filePath("N56E024.hgt"), size, [](int r, int c) { return 100 + c / 4 - r / 8; }));
        HgtTileSource source(dir.path());
        QVERIFY(source.isUsable());
        QCOMPARE(source.tileCount(), 1);
        const double span = size - 1;
        for (const auto &[lat, lon] : {std::pair{56.5, 24.5}, {56.0001, 24.9999}, {56.999, 24.001}, {56.25, 24.75}}) {
            const ElevationSample s = source.sample({lat, lon});
            QVERIFY(s.hasValue());
            const double y = (57 - lat) * span, x = (lon - 24) * span;
            // The posts hold floor(c/4) - floor(r/8): compare with the bilinear of the posts around.
            const int r0 = int(y), c0 = int(x);
            auto h = [](int r, int c) { return 100.0 + c / 4 - r / 8; };
            const double fy = y - r0, fx = x - c0;
            const double expected = (1 - fy) * ((1 - fx) * h(r0, c0) + fx * h(r0, c0 + 1)) + fy * ((1 - fx) * h(r0 + 1, c0) + fx * h(r0 + 1, c0 + 1));
            QVERIFY2(std::abs(s.ground - expected) < 1e-6, qPrintable(QStringLiteral("%1 vs %2").arg(s.ground).arg(expected)));
        }
        // The corners: row 0 is north, column 0 west.
        QCOMPARE(source.sample({57.0, 24.0}).ground, 100.0);
        QCOMPARE(source.sample({56.0, 25.0}).ground, 100.0 + (size - 1) / 4 - (size - 1) / 8);
        QVERIFY(!source.sample({55.9, 24.5}).hasValue());  // no tile there: no data, not 0
    }

    void peak()
    {
        QTemporaryDir dir;
        QVERIFY(writeHgt(dir.filePath("N56E024.hgt"), 3601, [](int r, int c) { return r == 1800 && c == 1800 ? 500 : 50; }));
        HgtTileSource source(dir.path());
        const double post = 1.0 / 3600;
        QCOMPARE(source.sample({57 - 1800 * post, 24 + 1800 * post}).ground, 500.0);
        QVERIFY(std::abs(source.sample({57 - 1800 * post, 24 + 1800.5 * post}).ground - 275.0) < 1e-6);
        QVERIFY(std::abs(source.sample({57 - 1800.5 * post, 24 + 1800.5 * post}).ground - 162.5) < 1e-6);
        QCOMPARE(source.sample({57 - 1802 * post, 24 + 1800 * post}).ground, 50.0);
    }

    void voids()
    {
        QTemporaryDir dir;
        QVERIFY(writeHgt(dir.filePath("N56E024.hgt"), 1201, [](int r, int c) { return r == 600 && c == 600 ? -32768 : 20; }));
        HgtTileSource source(dir.path());
        const double post = 1.0 / 1200;
        const ElevationSample on = source.sample({57 - 600 * post, 24 + 600 * post});
        QCOMPARE(on.status, SampleStatus::NoData);
        QVERIFY(std::isnan(on.ground));
        QCOMPARE(source.sample({57 - 600.5 * post, 24 + 599.5 * post}).status, SampleStatus::NoData);  // a cell touching it
        QCOMPARE(source.sample({57 - 601 * post, 24 + 600 * post}).ground, 20.0);   // the next post: the void has no weight
        QCOMPARE(source.sample({57 - 602.5 * post, 24 + 600.5 * post}).ground, 20.0);
    }

    // Two tiles meeting at 25°E with a plane running across both: no step at the seam.
    void edge()
    {
        QTemporaryDir dir;
        // 1 m per post eastwards, continuous: the east tile's column 0 repeats the west tile's last.
        QVERIFY(writeHgt(dir.filePath("N56E024.hgt"), 1201, [](int, int c) { return c; }));
        QVERIFY(writeHgt(dir.filePath("N56E025.hgt"), 1201, [](int, int c) { return 1200 + c; }));
        HgtTileSource source(dir.path());
        const double post = 1.0 / 1200;
        double previous = source.sample({56.5, 25 - 20 * post * 0.999}).ground;
        for (int k = -19; k <= 20; ++k) {
            const ElevationSample s = source.sample({56.5, 25 + k * post * 0.999});
            QVERIFY(s.hasValue());
            QVERIFY2(std::abs(s.ground - previous - 0.999) < 1e-6, qPrintable(QStringLiteral("%1: %2 after %3").arg(k).arg(s.ground).arg(previous)));
            previous = s.ground;
        }
        QCOMPARE(source.sample({56.5, 25.0}).ground, 1200.0);
        // The seam where only the east tile exists: the point on the edge still has its post.
        QTemporaryDir east;
        QVERIFY(writeHgt(east.filePath("N56E025.hgt"), 1201, [](int, int c) { return 1200 + c; }));
        HgtTileSource onlyEast(east.path());
        QCOMPARE(onlyEast.sample({56.5, 25.0}).ground, 1200.0);
        QVERIFY(!onlyEast.sample({56.5, 24.9999}).hasValue());
    }

    void corruptFiles()
    {
        QTemporaryDir dir;
        const QByteArray good = hgtBytes(1201, [](int, int) { return 7; });
        QVERIFY(writeFile(dir.filePath("N56E024.hgt"), good.left(good.size() - 2)));  // truncated by one post
        QVERIFY(writeFile(dir.filePath("N56E025.hgt"), good + "xx"));                  // one post too many
        QByteArray insane = good;
        insane[2 * (1201 * 7 + 9)] = char(0x4e);  // 0x4e07 = 19975 m at row 7, column 9
        QVERIFY(writeFile(dir.filePath("N56E026.hgt"), insane));
        QVERIFY(writeFile(dir.filePath("N56E027.hgt"), good));
        HgtTileSource source(dir.path());
        QVERIFY(source.isUsable());  // a folder is usable; its bad tiles are not
        for (double lon : {24.5, 25.5, 26.5})
            QCOMPARE(source.sample({56.5, lon}).status, SampleStatus::NoData);
        QCOMPARE(source.sample({56.5, 27.5}).ground, 7.0);
        const QStringList problems = source.problems();
        QCOMPARE(problems.size(), 3);
        QVERIFY(problems[0].contains(QStringLiteral("N56E024.hgt")) || problems[1].contains(QStringLiteral("N56E024.hgt"))
                || problems[2].contains(QStringLiteral("N56E024.hgt")));
        QVERIFY(problems.join('\n').contains(QStringLiteral("2884800 bytes is not an SRTM tile")));
        QVERIFY(problems.join('\n').contains(QStringLiteral("height 19975 m at row 7, column 9")));
        QVERIFY(!source.openAll());

        // One file given directly: checked at once, unusable with the reason.
        HgtTileSource single(dir.filePath("N56E024.hgt"));
        QVERIFY(!single.isUsable());
        QVERIFY(single.error().contains(dir.filePath("N56E024.hgt")));
        QCOMPARE(single.sample({56.5, 24.5}).status, SampleStatus::NoData);
        HgtTileSource badName(dir.filePath("nope.bin"));
        QVERIFY(!badName.isUsable());
        QVERIFY(badName.error().contains(QStringLiteral("no such file")));
        QVERIFY(writeFile(dir.filePath("tile.hgt"), good));
        HgtTileSource unnamed(dir.filePath("tile.hgt"));
        QVERIFY(!unnamed.isUsable());
        QVERIFY(unnamed.error().contains(QStringLiteral("NxxEyyy.hgt")));
        HgtTileSource fine(dir.filePath("N56E027.hgt"));
        QVERIFY(fine.isUsable());
        QCOMPARE(fine.sample({56.2, 27.2}).ground, 7.0);
    }

    void fromDataRejectsEverySize()
    {
        QString error;
        for (qsizetype n : {qsizetype(0), qsizetype(1), qsizetype(2884801), qsizetype(2884803)}) {
            const QByteArray bytes(n, '\0');
            QVERIFY(!HgtTile::fromData(bytes, {0, 0}, QStringLiteral("x.hgt"), &error));
            QVERIFY(error.startsWith(QStringLiteral("x.hgt: ")));
        }
    }
};

QTEST_GUILESS_MAIN(TstHgtTiles)
#include "tst_hgttiles.moc"
