// KML: the good polygons from QGroundControl's test data import as area-scan boundaries, the
// broken ones fail with a line number, and an exported route reads back in any KML parser.
#include "AreaScanPlanner.h"
#include "FlightPath.h"
#include "KmlFormat.h"
#include "MissionFiles.h"
#include "MissionSamples.h"

#include <QXmlStreamReader>
#include <QtTest>

using namespace sortie::mission;
using namespace sortie::mission::formats;
using namespace sortie::mission::test;

class TestKml : public QObject
{
    Q_OBJECT
private slots:
    void goodPolygon()
    {
        const Result<ImportedPolygon> p = loadPolygon(samplePath(QStringLiteral("PolygonGood.kml")));
        QVERIFY2(p.ok(), p.ok() ? "" : qPrintable(p.error().toString()));
        QCOMPARE(int(p->polygon.size()), 4);  // the closing vertex is dropped
        QCOMPARE(p->name, QStringLiteral("Untitled Polygon"));
        QCOMPARE(p->polygon[0].longitude, -122.1059149362712);
        QCOMPARE(p->polygon[0].latitude, 47.65965281788451);
        AreaScan scan;
        scan.polygon = p->polygon;
        scan.parameters.altitude = 40;
        QVERIFY(planAreaScan(scan).ok());
    }

    void closedPolylineIsABoundary()
    {
        const Result<ImportedPolygon> p = loadPolygon(samplePath(QStringLiteral("polyline.kml")));
        QVERIFY2(p.ok(), p.ok() ? "" : qPrintable(p.error().toString()));
        QCOMPARE(int(p->polygon.size()), 8);
        QCOMPARE(p->polygon[1].latitude, 46.47493);
    }

    void brokenFilesFailWithTheLine_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("line");
        QTest::addColumn<QString>("words");
        QTest::newRow("bad xml") << "PolygonBadXml.kml" << 1 << "not valid KML";
        QTest::newRow("bad coordinates node") << "PolygonBadCoordinatesNode.kml" << 1 << "not valid KML";
        QTest::newRow("missing node") << "PolygonMissingNode.kml" << 33 << "no Polygon";
    }
    void brokenFilesFailWithTheLine()
    {
        QFETCH(QString, file);
        QFETCH(int, line);
        QFETCH(QString, words);
        const Result<ImportedPolygon> p = loadPolygon(samplePath(file));
        QVERIFY(!p.ok());
        QCOMPARE(p.error().file, samplePath(file));
        QVERIFY2(p.error().line == line, qPrintable(p.error().toString()));
        QVERIFY2(p.error().message.contains(words), qPrintable(p.error().message));
    }

    void badCoordinates_data()
    {
        QTest::addColumn<QByteArray>("coordinates");
        QTest::addColumn<int>("line");
        QTest::newRow("not a number") << QByteArray("1,2,0\n 3,x,0 5,6,0 1,2,0") << 4;
        QTest::newRow("out of range") << QByteArray("1,2 3,4\n\n 5,96 1,2") << 5;
        QTest::newRow("too few") << QByteArray("1,2 3,4 1,2") << 3;
        QTest::newRow("one number") << QByteArray("1,2 3") << 3;
    }
    void badCoordinates()
    {
        QFETCH(QByteArray, coordinates);
        QFETCH(int, line);
        const QByteArray doc = "<?xml version=\"1.0\"?>\n<kml xmlns=\"http://www.opengis.net/kml/2.2\"><Placemark><Polygon><outerBoundaryIs><LinearRing>\n"
                               "<coordinates>" + coordinates + "</coordinates></LinearRing></outerBoundaryIs></Polygon></Placemark></kml>\n";
        const Result<ImportedPolygon> p = readKmlPolygon(doc);
        QVERIFY(!p.ok());
        QVERIFY2(p.error().line == line, qPrintable(p.error().toString()));
    }

    void openLineIsRefused()
    {
        const QByteArray doc = "<kml><Placemark><LineString><coordinates>1,2 3,4 5,6</coordinates></LineString></Placemark></kml>";
        const Result<ImportedPolygon> p = readKmlPolygon(doc);
        QVERIFY(!p.ok());
        QVERIFY(p.error().message.contains(QStringLiteral("open")));
    }

    void exportedRouteReadsBack()
    {
        Route r = mavlinkRoute();
        r.settings.name = QStringLiteral("Quay <north> & pier");
        r.segments.push_back(squareScan({56.96, 24.11}, 300, 60));
        const QByteArray kml = writeKmlRoute(r);
        // The scan's polygon is the boundary a KML import finds (the open flight path is not one).
        const Result<ImportedPolygon> polygon = readKmlPolygon(kml);
        QVERIFY2(polygon.ok(), polygon.ok() ? "" : qPrintable(polygon.error().toString()));
        QVERIFY(polygon->polygon == std::get<AreaScan>(r.segments.back()).polygon);
        // Line strings hold the whole flown path, each run with its altitude mode.
        QXmlStreamReader xml(kml);
        int linePoints = 0, lines = 0, points = 0;
        QStringList modes;
        bool inLine = false;
        while (!xml.atEnd()) {
            xml.readNext();
            if (xml.isStartElement() && xml.name() == QLatin1String("LineString")) { inLine = true; ++lines; }
            if (xml.isEndElement() && xml.name() == QLatin1String("LineString")) inLine = false;
            if (xml.isStartElement() && xml.name() == QLatin1String("Point")) ++points;
            if (xml.isStartElement() && xml.name() == QLatin1String("altitudeMode") && inLine) modes << xml.readElementText();
            if (xml.isStartElement() && xml.name() == QLatin1String("coordinates") && inLine)
                linePoints += int(xml.readElementText().split(QLatin1Char(' '), Qt::SkipEmptyParts).size());
        }
        QVERIFY(!xml.hasError());
        const int path = int(flightPath(r).size());
        QCOMPARE(lines, 3);  // AGL, the AMSL waypoint, AGL again
        QCOMPARE(modes, (QStringList{"relativeToGround", "absolute", "relativeToGround"}));
        QCOMPARE(linePoints, path + lines - 1);  // each later run repeats its predecessor's last point
        QCOMPARE(points, int(r.segments.size()) - 1);
        QVERIFY(kml.contains("<name>Quay &lt;north&gt; &amp; pier</name>"));
        QVERIFY(kml.contains("24.1023456789012,56.9512345678901,30"));
    }
};

QTEST_GUILESS_MAIN(TestKml)
#include "tst_kml.moc"
