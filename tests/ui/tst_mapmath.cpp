// Pure map arithmetic: projection, viewport, graticule, scale bar, clipping, route frames, label
// placement, units.
#include "DisplayUnits.h"
#include "Graticule.h"
#include "LabelPlacer.h"
#include "LandTileRenderer.h"
#include "MapViewport.h"
#include "RouteFrame.h"
#include "ScaleBarLength.h"
#include "TileKey.h"
#include "WebMercator.h"

#include <QFontMetrics>
#include <QTest>

#include <cmath>
#include <random>

using namespace sortie::ui;

class TestMapMath : public QObject
{
    Q_OBJECT

private slots:
    void projectionCorners()
    {
        QCOMPARE(WebMercator::project(0, 0), QPointF(0.5, 0.5));
        const QPointF northWest = WebMercator::project(WebMercator::kMaxLatitude, -180);
        QVERIFY(std::abs(northWest.x()) < 1e-12);
        QVERIFY(std::abs(northWest.y()) < 1e-9);
        const QPointF southEast = WebMercator::project(-90, 180); // clamped to the map's edge
        QVERIFY(std::abs(southEast.x() - 1.0) < 1e-12);
        QVERIFY(std::abs(southEast.y() - 1.0) < 1e-9);
    }

    void projectionRoundTrip()
    {
        std::mt19937 random(7);
        std::uniform_real_distribution<double> lat(-85, 85), lon(-179.999, 179.999);
        for (int i = 0; i < 1000; ++i) {
            const double a = lat(random), b = lon(random);
            const QGeoCoordinate back = WebMercator::unproject(WebMercator::project(a, b));
            QVERIFY2(std::abs(back.latitude() - a) < 1e-9 && std::abs(back.longitude() - b) < 1e-9,
                     qPrintable(QStringLiteral("%1,%2").arg(a).arg(b)));
        }
        // x outside [0, 1] is the same place one world over.
        QVERIFY(std::abs(WebMercator::unproject(QPointF(1.25, 0.5)).longitude() - -90.0) < 1e-9);
    }

    void metersPerPixel()
    {
        // 2 pi R / 256 at the equator, zoom 0; halves per zoom level; cos(lat) shrinks it.
        QVERIFY(std::abs(WebMercator::metersPerPixel(0, 0) - 156543.03392804097) < 1e-6);
        QVERIFY(std::abs(WebMercator::metersPerPixel(0, 10) - 156543.03392804097 / 1024) < 1e-6);
        QVERIFY(std::abs(WebMercator::metersPerPixel(60, 0) - 156543.03392804097 / 2) < 1e-6);
    }

    void viewportConversions()
    {
        MapViewport view(WebMercator::project(56.95, 24.1), 12, QSizeF(800, 600));
        QCOMPARE(view.toScreen(view.centre()), QPointF(400, 300));
        const QPointF p(123.5, 456.25);
        const QPointF back = view.toScreen(view.toNormalised(p));
        QVERIFY(std::abs(back.x() - p.x()) < 1e-6 && std::abs(back.y() - p.y()) < 1e-6);
        const QGeoCoordinate c = view.screenToGeo(QPointF(400, 300));
        QVERIFY(std::abs(c.latitude() - 56.95) < 1e-9 && std::abs(c.longitude() - 24.1) < 1e-9);
        // One pixel at zoom 12 is 1/(256 * 4096) of the world.
        const QPointF right = view.toNormalised(QPointF(401, 300));
        QVERIFY(std::abs((right.x() - view.centre().x()) * 256 * 4096 - 1.0) < 1e-6);
    }

    void viewportPanAndZoomAround()
    {
        MapViewport view(QPointF(0.5, 0.5), 4, QSizeF(800, 600));
        const QPointF anchor(650, 120);
        const QGeoCoordinate under = view.screenToGeo(anchor);
        view.zoomAround(anchor, 7.5);
        QCOMPARE(view.zoom(), 7.5);
        const QPointF still = view.geoToScreen(under);
        QVERIFY2(std::abs(still.x() - anchor.x()) < 1e-6 && std::abs(still.y() - anchor.y()) < 1e-6,
                 qPrintable(QStringLiteral("%1,%2").arg(still.x()).arg(still.y())));

        const QGeoCoordinate before = view.screenToGeo(QPointF(100, 100));
        view.panByPixels(QPointF(30, -20));
        const QPointF moved = view.geoToScreen(before);
        QVERIFY(std::abs(moved.x() - 130) < 1e-6 && std::abs(moved.y() - 80) < 1e-6);

        view.setZoom(99);
        QCOMPARE(view.zoom(), MapViewport::kMaxZoom);
    }

    void viewportWrapsAtTheAntimeridian()
    {
        MapViewport view(WebMercator::project(0, 179), 6, QSizeF(800, 600));
        // 2 degrees east of the centre, across the antimeridian, is to the right.
        const QPointF east = view.geoToScreen(QGeoCoordinate(0, -179));
        const double pixelsPerDegree = 256 * 64 / 360.0;
        QVERIFY(std::abs(east.x() - (400 + 2 * pixelsPerDegree)) < 1e-6);
        // Panning across keeps the centre in [0, 1).
        view.panByPixels(QPointF(-4 * pixelsPerDegree, 0));
        QVERIFY(view.centre().x() >= 0 && view.centre().x() < 1);
        QVERIFY(std::abs(WebMercator::unproject(view.centre()).longitude() - -177) < 1e-9);
    }

    void tileKeys()
    {
        const TileKey key{5, 17, 9};
        QVERIFY(key.isValid());
        QCOMPARE(key.parent(), (TileKey{4, 8, 4}));
        QVERIFY(!(TileKey{3, 8, 0}.isValid()));
        QVERIFY(key.packed() != (TileKey{5, 9, 17}).packed());
        QVERIFY((TileKey{20, 1, 0}).packed() != (TileKey{20, 0, 1}).packed());
        QCOMPARE(key.toString(), QStringLiteral("5/17/9"));
    }

    void graticuleInterval()
    {
        MapViewport world(QPointF(0.5, 0.5), 1, QSizeF(800, 600)); // 512 px for 360 degrees
        QCOMPARE(Graticule::interval(world), 30.0); // the widest step, even if closer than asked
        MapViewport city(QPointF(0.5, 0.5), 14, QSizeF(800, 600)); // ~11650 px per degree
        QCOMPARE(Graticule::interval(city), 0.01);
        QCOMPARE(Graticule::label(-12.5, 0.5, true), QStringLiteral("12.5°S"));
        QCOMPARE(Graticule::label(30, 10, false), QStringLiteral("30°E"));
        QCOMPARE(Graticule::label(1e-12, 0.01, false), QStringLiteral("0°"));
    }

    // Labels stay whole inside the view, in their bands, and never cross, at every zoom and place.
    void graticuleLabelsKeepToTheirBands()
    {
        const QFontMetrics metrics(Graticule::labelFont(QFont()));
        const QMarginsF bands = Graticule::labelBands(metrics);
        QVERIFY(bands.top() > metrics.height() && bands.left() > metrics.horizontalAdvance(QStringLiteral("56.9765°N")));
        int seen = 0;
        for (double zoom : {2.0, 6.5, 11.0, 13.9, 17.0, 19.5}) {
            for (QPointF centre : {QPointF(0.5, 0.5), WebMercator::project(56.97, 24.07), WebMercator::project(-33.9, 151.2)}) {
                const MapViewport view(centre, zoom, QSizeF(707, 678));
                const auto labels = Graticule::labels(view, metrics);
                seen += int(labels.size());
                for (size_t i = 0; i < labels.size(); ++i) {
                    const QRectF r = labels[i].rect;
                    QVERIFY(QRectF(QPointF(0, 0), view.size()).contains(r));
                    QVERIFY2(r.bottom() <= bands.top() || r.right() <= bands.left(), qPrintable(labels[i].text)); // in a band
                    for (size_t j = i + 1; j < labels.size(); ++j)
                        QVERIFY2(!r.intersects(labels[j].rect), qPrintable(labels[i].text + QStringLiteral(" / ") + labels[j].text));
                }
            }
        }
        QVERIFY(seen > 30);
    }

    void scaleBar()
    {
        ScaleBarLength metric = ScaleBarLength::choose(3.0, 120, false); // up to 360 m
        QCOMPARE(metric.label, QStringLiteral("200 m"));
        QVERIFY(std::abs(metric.pixels - 200.0 / 3.0) < 1e-9);
        QCOMPARE(ScaleBarLength::choose(100.0, 120, false).label, QStringLiteral("10 km"));
        ScaleBarLength imperial = ScaleBarLength::choose(3.0, 120, true); // 1181 ft
        QCOMPARE(imperial.label, QStringLiteral("1000 ft"));
        QCOMPARE(ScaleBarLength::choose(100.0, 120, true).label, QStringLiteral("5 mi"));
        QCOMPARE(ScaleBarLength::choose(0, 120, false).pixels, 0.0);
    }

    void clipRing()
    {
        const std::vector<QPointF> square{{0, 0}, {4, 0}, {4, 4}, {0, 4}};
        const auto clipped = LandTileRenderer::clipRing(square, QRectF(2, 1, 10, 2), 0);
        // The part of the square inside the rectangle: x 2..4, y 1..3.
        QVERIFY(!clipped.empty());
        double left = 1e9, right = -1e9, top = 1e9, bottom = -1e9;
        for (const QPointF &p : clipped) {
            left = std::min(left, p.x());
            right = std::max(right, p.x());
            top = std::min(top, p.y());
            bottom = std::max(bottom, p.y());
        }
        QCOMPARE(QRectF(QPointF(left, top), QPointF(right, bottom)), QRectF(2, 1, 2, 2));
        QVERIFY(LandTileRenderer::clipRing(square, QRectF(10, 10, 1, 1), 0).empty());
        // Shifted by one world to the right.
        QCOMPARE(LandTileRenderer::clipRing(square, QRectF(14, 1, 1, 1), 10).size(), size_t(4));
    }

    void routeFrameCullsAndLabels()
    {
        std::vector<QPointF> points;
        for (int i = 0; i < 1000; ++i)
            points.push_back(WebMercator::project(56.9 + i * 1e-4, 24.1 + (i % 2) * 1e-4));
        RouteFrame::Input input;
        input.points = &points;
        std::vector<bool> selected(points.size(), false);
        selected[500] = true;
        input.selected = &selected;
        input.current = 500;
        // Zoomed in on waypoint 500: only its neighbours are on screen.
        MapViewport view(points[500], 19, QSizeF(400, 300));
        RouteFrame frame = RouteFrame::build(input, view);
        QVERIFY(frame.visibleWaypoints > 1);
        QVERIFY(frame.visibleWaypoints < 100);
        QVERIFY(!frame.legs.empty());
        const RouteFrame::Marker &top = frame.markers.back();
        QCOMPARE(top.row, 500);
        QVERIFY(top.flags & RouteFrame::Selected);
        QVERIFY(top.flags & RouteFrame::Current);
        QVERIFY(top.flags & RouteFrame::Labelled);

        // Zoomed out, all 1000 overlap: few labels, every waypoint still drawn.
        MapViewport far(points[500], 10, QSizeF(400, 300));
        frame = RouteFrame::build(input, far);
        QCOMPARE(frame.visibleWaypoints, 1000);
        QCOMPARE(int(frame.markers.size()), 1000);
        QVERIFY(frame.labelledWaypoints >= 1 && frame.labelledWaypoints < 50);

        // A dragged waypoint is drawn where the drag is.
        input.draggedRows = {500};
        input.dragOffset = QPointF(10.0 / view.scale(), 0);
        frame = RouteFrame::build(input, view);
        const QPointF expected = view.toScreen(points[500]) + QPointF(10, 0);
        QCOMPARE(int(frame.movingMarkers.size()), 1);
        QVERIFY(std::abs(frame.movingMarkers.front().position.x() - expected.x()) < 1e-6);
        QCOMPARE(int(frame.movingLegs.size()), 2); // 499-500 and 500-501 move with it
        for (const RouteFrame::Marker &marker : frame.markers)
            QVERIFY(marker.row != 500);
        // A further move rebuilds the moving part only.
        const std::vector<QPolygonF> stillLegs = frame.legs;
        input.dragOffset = QPointF(25.0 / view.scale(), 5.0 / view.scale());
        frame.updateMoving(input, view);
        QVERIFY((frame.movingMarkers.front().position - (view.toScreen(points[500]) + QPointF(25, 5))).manhattanLength() < 1e-6);
        QCOMPARE(frame.legs, stillLegs);
        QCOMPARE(frame.movingLegs.front().last(), frame.movingMarkers.front().position);
    }

    void routeFrameSimplifiesStraightRuns()
    {
        // 500 waypoints on a straight line, then 500 back on a parallel one: legs of 2 + 2 points.
        std::vector<QPointF> points;
        for (int i = 0; i < 500; ++i)
            points.push_back(WebMercator::project(56.95, 24.0 + i * 1e-4));
        for (int i = 499; i >= 0; --i)
            points.push_back(WebMercator::project(56.951, 24.0 + i * 1e-4));
        RouteFrame::Input input;
        input.points = &points;
        const MapViewport view(WebMercator::project(56.9505, 24.025), 12, QSizeF(1000, 600));
        const RouteFrame frame = RouteFrame::build(input, view);
        QCOMPARE(int(frame.legs.size()), 1);
        QCOMPARE(frame.legs.front().size(), 4);
        QCOMPARE(frame.legs.front().first(), view.toScreen(points.front()));
        QCOMPARE(frame.legs.front().last(), view.toScreen(points.back()));
        QCOMPARE(frame.visibleWaypoints, 1000); // every waypoint keeps its marker
    }

    void routeFrameAcrossTheAntimeridian()
    {
        std::vector<QPointF> points{WebMercator::project(0, 179.9), WebMercator::project(0, -179.9)};
        RouteFrame::Input input;
        input.points = &points;
        MapViewport view(WebMercator::project(0, 180), 10, QSizeF(800, 600));
        const RouteFrame frame = RouteFrame::build(input, view);
        QCOMPARE(int(frame.legs.size()), 1);
        const QPolygonF leg = frame.legs.front();
        // A short leg across the screen's middle, not one around the world.
        QVERIFY(std::abs(leg.last().x() - leg.first().x()) < 200);
        QVERIFY(leg.first().x() < 400 && leg.last().x() > 400);
    }

    // Labels beside their marks unless a label placed earlier or another mark is in the way; then
    // stacked below it, never overlapping, and the first placed keeps its place.
    void labelPlacerKeepsLabelsApart()
    {
        const QSizeF size(60, 15);
        // Alone: beside its mark, 16 px right, its middle 10 px above.
        LabelPlacer alone({QPointF(100, 100)});
        const LabelPlacer::Placement single = alone.place(0, size);
        QCOMPARE(single.rect, QRectF(116, 82.5, 60, 15));
        QVERIFY(!single.moved);

        // Three marks at one spot: the first placed stays, the others go below, one by one.
        LabelPlacer stacked({QPointF(100, 100), QPointF(100, 100), QPointF(100, 100)});
        std::vector<LabelPlacer::Placement> placed;
        for (size_t mark : {size_t(2), size_t(0), size_t(1)})
            placed.push_back(stacked.place(mark, size));
        QVERIFY(!placed[0].moved);
        QVERIFY(placed[1].moved && placed[2].moved);
        for (size_t a = 0; a < placed.size(); ++a)
            for (size_t b = a + 1; b < placed.size(); ++b)
                QVERIFY(!placed[a].rect.intersects(placed[b].rect));
        QVERIFY(placed[0].rect.top() < placed[1].rect.top() && placed[1].rect.top() < placed[2].rect.top());

        // Another mark right of this one: the label would cover it, so it moves down and clear.
        LabelPlacer beside({QPointF(100, 100), QPointF(140, 92)});
        const LabelPlacer::Placement clear = beside.place(0, size);
        QVERIFY(clear.moved);
        QVERIFY(!clear.rect.intersects(QRectF(128, 80, 24, 24)));
        // Far apart, nothing moves.
        LabelPlacer apart({QPointF(100, 100), QPointF(400, 400)});
        QVERIFY(!apart.place(0, size).moved && !apart.place(1, size).moved);
    }

    void displayUnits()
    {
        DisplayUnits units;
        QCOMPARE(units.formatDistance(1234.5), QStringLiteral("1.23 km"));
        QCOMPARE(units.formatDistance(5.24), QStringLiteral("5.2 m"));
        QCOMPARE(units.formatSpeed(10), QStringLiteral("10.0 m/s"));
        units.setSystemName(QStringLiteral("imperial"));
        QVERIFY(units.isImperial());
        QCOMPARE(units.formatAltitude(30.48), QStringLiteral("100 ft"));
        QCOMPARE(units.formatDistance(3218.688), QStringLiteral("2.00 mi"));
        QCOMPARE(units.formatSpeed(1609.344 / 3600.0 * 30), QStringLiteral("30.0 mph"));
        QCOMPARE(units.formatLatLon(56.5, -24.25), QStringLiteral("56.500000, -24.250000"));
        units.setCoordinateFormat(DisplayUnits::CoordinateFormat::DegreesMinutesSeconds);
        QCOMPARE(units.formatLatLon(56.5, -24.25), QStringLiteral("56°30′00.00″N 24°15′00.00″W"));
        QCOMPARE(units.formatCoordinate(QGeoCoordinate()), QStringLiteral("—"));
    }

    void displayUnitsForTheInstruments()
    {
        DisplayUnits units;
        QCOMPARE(units.formatDuration(0), QStringLiteral("0:00"));
        QCOMPARE(units.formatDuration(245.4), QStringLiteral("4:05"));
        QCOMPARE(units.formatDuration(3723), QStringLiteral("1:02:03"));
        QCOMPARE(units.formatDuration(qQNaN()), QStringLiteral("—"));
        QCOMPARE(units.formatAngle(30.2), QStringLiteral("30°"));
        QCOMPARE(units.formatAngle(-0.1), QStringLiteral("0°"));
        QCOMPARE(units.formatAngle(-45), QStringLiteral("-45°"));
        QCOMPARE(units.formatHeading(-90), QStringLiteral("270°"));
        QCOMPARE(units.formatHeading(366), QStringLiteral("006°"));
        QCOMPARE(units.formatHeading(qQNaN()), QStringLiteral("—"));
        // The simulator's HCI vehicles send a voltage and no level: the voltage is shown.
        QCOMPARE(units.formatBattery(22.43, qQNaN()), QStringLiteral("22.4 V"));
        QCOMPARE(units.formatBattery(qQNaN(), 0.871), QStringLiteral("87 %"));
        QCOMPARE(units.formatBattery(22.43, 0.871), QStringLiteral("87 %  22.4 V"));
        QCOMPARE(units.formatBattery(qQNaN(), qQNaN()), QStringLiteral("—"));
        QCOMPARE(units.formatLinkState(0), QStringLiteral("disconnected"));
        QCOMPARE(units.formatLinkState(2), QStringLiteral("connected"));
        QCOMPARE(units.formatLinkState(3), QStringLiteral("link lost"));
        QCOMPARE(units.formatLinkState(17), QStringLiteral("—"));
    }
};

QTEST_MAIN(TestMapMath) // fonts (graticule labels) need a QGuiApplication
#include "tst_mapmath.moc"
