// Every figure a UgCS segment stands on, drawn and edited through the real client window offscreen
// against the embedded simulator, the way an operator does it: pick the tool, click the figure on
// the map, drag its handles, click an edge to add a corner, right-click one to remove it, type a
// parameter in the editor generated from the algorithm's description. Each gesture is one undo
// step that undo takes back exactly, the path drawn on the map follows each edit, and a .sortie
// file written afterwards reads back with the figure and its parameters.
//
// One test per figure: a circle (Circle), a polyline (Corridor mapping), a polygon other than the
// area scan (Perimeter), a point (Expanding square, the point tool the picker offers; take-off and
// landing are placed as waypoints).
#include "AreaScanLayer.h"
#include "ClientWindow.h"
#include "MapView.h"
#include "MissionFiles.h"
#include "QuickScene.h"
#include "RouteEditor.h"
#include "RouteLayer.h"
#include "RouteModel.h"

#include <QQuickItem>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

#include <cmath>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

// A step of a flow: stops the test where a helper failed.
#define STEP(call)                                                                                                     \
    do {                                                                                                               \
        call;                                                                                                          \
        if (QTest::currentTestFailed())                                                                                \
            return;                                                                                                    \
    } while (false)

using namespace sortie;
using mission::AlgorithmSegment;
using mission::GeoPoint;
using mission::Segment;
using ui::AreaScanLayer;
using ui::MapView;
using ui::RouteLayer;

namespace {

// The demo route has four waypoints; the figure drawn is the fifth row.
constexpr int kRow = 4;
// By objectName, through the item tree (a Repeater's delegates are only there).
QQuickItem *findItem(QQuickItem *root, const QString &name)
{
    for (QQuickItem *child : root->childItems()) {
        if (child->objectName() == name)
            return child;
        if (QQuickItem *found = findItem(child, name))
            return found;
    }
    return nullptr;
}

QPoint centreOf(QQuickItem *item)
{
    return item->mapToScene(QPointF(item->width() / 2, item->height() / 2)).toPoint();
}

// Metres between two positions (tens of metres apart: a local flat earth is exact to centimetres).
double metersBetween(const GeoPoint &a, const GeoPoint &b)
{
    const double north = (b.latitude - a.latitude) * 111'320.0;
    const double east = (b.longitude - a.longitude) * 111'320.0 * std::cos(a.latitude * M_PI / 180.0);
    return std::hypot(north, east);
}

} // namespace

class TestFigureFlows : public QObject
{
    Q_OBJECT

    std::unique_ptr<test::ClientWindow> m_client;

    QQuickWindow *window() const { return m_client->window(); }
    client::RouteDocument *doc() const { return m_client->missions().document(); }
    MapView *map() const { return m_client->page("missionPage")->property("map").value<MapView *>(); }
    RouteLayer *routeLayer() const { return find<RouteLayer>("routeLayer"); }
    AreaScanLayer *areaLayer() const { return find<AreaScanLayer>("areaLayer"); }
    const Segment &segment() const { return doc()->model()->segment(kRow); }
    const AlgorithmSegment &figureSegment() const { return std::get<AlgorithmSegment>(segment()); }
    QString parameter(const char *name) const
    {
        const QString *value = figureSegment().value(QString::fromLatin1(name));
        return value ? *value : QString();
    }
    std::vector<GeoPoint> figure() const { return mission::figureOf(segment()); }
    GeoPoint corner(int i) const { return figure().at(size_t(i)); }
    QVariantList drawnPath() const { return areaLayer()->path(); }

    template<typename T = QQuickItem>
    T *find(const char *name) const
    {
        const QString key = QString::fromLatin1(name);
        T *found = window()->findChild<T *>(key);
        if (!found)
            found = qobject_cast<T *>(findItem(window()->contentItem(), key));
        if (!found)
            qWarning("no item named %s", name);
        return found;
    }
    // Scene position of a point of the map item.
    QPoint onMap(QPointF position) const { return map()->mapToScene(position).toPoint(); }
    // A clear stretch of the map below the demo route (the route is fitted the same way every time),
    // above the terrain profile.
    QPointF base() const { return {450, map()->height() - 150}; }
    GeoPoint geoAt(QPointF position) const
    {
        const QGeoCoordinate c = map()->toCoordinate(position);
        return {c.latitude(), c.longitude()};
    }
    // Where a figure's point shows on the map item.
    QPointF onMapItem(const GeoPoint &p) const { return map()->fromCoordinate(QGeoCoordinate(p.latitude, p.longitude)); }

    void click(const char *name)
    {
        QQuickItem *item = find(name);
        QVERIFY2(item, name);
        QTRY_VERIFY2(item->isVisible() && item->isEnabled(), name);
        QTest::mouseClick(window(), Qt::LeftButton, {}, centreOf(item));
    }
    // Types into a field of the segment editor as an operator does: click it, select all, type, Return.
    void type(const char *field, const QString &text)
    {
        QQuickItem *item = find(field);
        QVERIFY2(item, field);
        QTRY_VERIFY2(item->isVisible() && item->width() > 0 && QRect(QPoint(), window()->size()).contains(centreOf(item)), field);
        QTest::mouseClick(window(), Qt::LeftButton, {}, centreOf(item));
        QTRY_VERIFY(item->hasActiveFocus());
        QTest::keyClick(window(), Qt::Key_A, Qt::ControlModifier);
        for (QChar c : text)
            QTest::keyClick(window(), c.toLatin1());
        QTest::keyClick(window(), Qt::Key_Return);
    }
    // A press, a few moves and a release (what a hand does; the layer starts a drag past a threshold).
    void drag(QPoint from, QPoint by)
    {
        QTest::mousePress(window(), Qt::LeftButton, {}, from);
        for (int i = 1; i <= 6; ++i)
            QTest::mouseMove(window(), from + QPoint(by.x() * i / 6, by.y() * i / 6));
        QTest::mouseRelease(window(), Qt::LeftButton, {}, from + by);
    }

    // Picks the drawing tool of `algorithm` (short class name) in the picker, with the keyboard,
    // and clicks `points` (map item positions, from base()); polylines and polygons are finished
    // with Create. The new segment becomes the current row and the editable figure on the map.
    void draw(const char *algorithm, const QList<QPointF> &points)
    {
        click("scanToolButton");
        QQuickItem *picker = find("segmentToolPicker");
        QVERIFY(picker);
        QTRY_VERIFY(picker->isVisible());
        // The tool by its algorithm, from the editor the picker lists.
        const mission::RouteEditor &editor = *doc()->editor();
        int wanted = -1;
        mission::DrawingTool tool;
        for (int i = 0; i < editor.drawingToolNames().size(); ++i) {
            if (editor.drawingTool(i).algorithm.endsWith(QLatin1String(algorithm))) {
                wanted = i;
                tool = editor.drawingTool(i);
            }
        }
        QCOMPARE(picker->property("model").toStringList(), editor.drawingToolNames());
        QVERIFY2(wanted >= 0, algorithm);
        picker->forceActiveFocus(Qt::TabFocusReason);
        QTRY_VERIFY(picker->hasActiveFocus());
        while (picker->property("currentIndex").toInt() < wanted)
            QTest::keyClick(window(), Qt::Key_Down);
        QCOMPARE(picker->property("currentIndex").toInt(), wanted);

        for (const QPointF &p : points) {
            QVERIFY(routeLayer()->waypointAt(base() + p) < 0 && routeLayer()->legAt(base() + p) < 0);
            QTest::mouseClick(window(), Qt::LeftButton, {}, onMap(base() + p));
        }
        if (!tool.oneClick) {
            QTRY_COMPARE(find("scanDraftLayer")->property("vertexCount").toInt(), int(points.size()));
            click("finishScanButton");
        }
        QTRY_COMPARE(routeLayer()->count(), kRow + 1);
        QCOMPARE(doc()->currentRow(), kRow);
        QTRY_COMPARE(areaLayer()->vertexCount(), tool.figure == mission::FigureType::Circle ? 1 : int(points.size()));
        QTRY_VERIFY(areaLayer()->isEditable());
        QVERIFY2(doc()->scanProblem().isEmpty(), qPrintable(doc()->scanProblem()));
        STEP(pathCaughtUp());
        QVERIFY(areaLayer()->transectPointCount() >= 2);
        for (int i = 0; i < int(points.size()); ++i)
            QVERIFY(metersBetween(corner(i), geoAt(base() + points[i])) < 0.05);
    }

    // Drags point `vertex` of the figure by `by` pixels: it lands where the mouse let go, the path
    // follows, and it is one undo step that undo takes back exactly.
    void dragVertex(int vertex, QPoint by)
    {
        const Segment before = segment();
        STEP(pathCaughtUp());
        const QVariantList pathBefore = drawnPath();
        const int steps = doc()->undoStack()->count();
        const QPointF at = onMapItem(corner(vertex));
        QCOMPARE(areaLayer()->vertexAt(at), vertex);
        const GeoPoint dropped = geoAt(at + QPointF(by));
        drag(onMap(at), by);
        QTRY_VERIFY2(metersBetween(corner(vertex), dropped) < 0.2,
                     qPrintable(QString::number(metersBetween(corner(vertex), dropped))));
        QCOMPARE(doc()->undoStack()->count(), steps + 1);
        STEP(pathCaughtUp());  // planned again off the drag (coalesced)
        QVERIFY(drawnPath() != pathBefore);
        STEP(undoRedo(before, pathBefore));
    }

    // A click on the middle of edge `edge` adds a corner there (after the edge's first point): one
    // undo step, and no waypoint is added under it.
    void insertCorner(int edge)
    {
        const Segment before = segment();
        STEP(pathCaughtUp());
        const QVariantList pathBefore = drawnPath();
        const std::vector<GeoPoint> corners = figure();
        const int steps = doc()->undoStack()->count();
        const QPointF middle = (onMapItem(corner(edge)) + onMapItem(corner((edge + 1) % int(corners.size())))) / 2;
        QCOMPARE(areaLayer()->edgeAt(middle), edge);
        const GeoPoint clicked = geoAt(map()->mapFromScene(QPointF(onMap(middle))));
        QTest::mouseClick(window(), Qt::LeftButton, {}, onMap(middle));
        QTRY_COMPARE(areaLayer()->vertexCount(), int(corners.size()) + 1);
        QCOMPARE(figure().size(), corners.size() + 1);
        QVERIFY(metersBetween(corner(edge + 1), clicked) < 0.2);
        QCOMPARE(doc()->undoStack()->count(), steps + 1);
        QCOMPARE(routeLayer()->count(), kRow + 1);
        STEP(pathCaughtUp());
        QVERIFY(drawnPath() != pathBefore);
        STEP(undoRedo(before, pathBefore));
        QTRY_COMPARE(areaLayer()->vertexCount(), int(corners.size()) + 1);
    }

    // A right click on corner `vertex` removes it: one undo step.
    void removeCorner(int vertex)
    {
        const Segment before = segment();
        STEP(pathCaughtUp());
        const QVariantList pathBefore = drawnPath();
        const std::vector<GeoPoint> corners = figure();
        const int steps = doc()->undoStack()->count();
        QTest::mouseClick(window(), Qt::RightButton, {}, onMap(onMapItem(corner(vertex))));
        QTRY_COMPARE(areaLayer()->vertexCount(), int(corners.size()) - 1);
        std::vector<GeoPoint> expected = corners;
        expected.erase(expected.begin() + vertex);
        QVERIFY(figure() == expected);
        QCOMPARE(doc()->undoStack()->count(), steps + 1);
        STEP(pathCaughtUp());
        QVERIFY(drawnPath() != pathBefore);
        STEP(undoRedo(before, pathBefore));
        QTRY_COMPARE(areaLayer()->vertexCount(), int(corners.size()) - 1);
    }

    // The path on the map is the one the segment as it is now flies (the preview plans at most once
    // a frame, so a drag's last step shows a frame later; reading the document's plans at once).
    void pathCaughtUp()
    {
        QTRY_VERIFY(!drawnPath().isEmpty() && drawnPath() == doc()->scanPath());
    }

    // The last edit undone restores `before` exactly, and the path drawn for it; redone, it is back.
    void undoRedo(const Segment &before, const QVariantList &pathBefore)
    {
        STEP(pathCaughtUp());
        const Segment after = segment();
        const QVariantList pathAfter = drawnPath();
        QVERIFY(!(after == before));
        doc()->undo();
        QVERIFY(segment() == before);
        QTRY_COMPARE(drawnPath(), pathBefore);
        doc()->redo();
        QVERIFY(segment() == after);
        QTRY_COMPARE(drawnPath(), pathAfter);
    }

    // Types a parameter in the generated editor: the segment carries it, the path is planned again,
    // one undo step.
    void typeParameter(const char *name, const QString &value)
    {
        const Segment before = segment();
        STEP(pathCaughtUp());
        const QVariantList pathBefore = drawnPath();
        const int steps = doc()->undoStack()->count();
        const QByteArray field = "segment_" + QByteArray(name);
        STEP(type(field.constData(), value));
        QTRY_COMPARE(parameter(name), value);
        QCOMPARE(doc()->undoStack()->count(), steps + 1);
        STEP(pathCaughtUp());
        QVERIFY(drawnPath() != pathBefore);
        QVERIFY(doc()->scanProblem().isEmpty());
        STEP(undoRedo(before, pathBefore));
    }

    // Written to a .sortie file and read back: the segment is the same, figure and parameters.
    void saveAndReadBack(const char *kind)
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("figure.sortie"));
        QVERIFY2(doc()->exportFile(QUrl::fromLocalFile(path)), qPrintable(doc()->message()));
        const auto loaded = mission::formats::loadMission(path);
        QVERIFY2(loaded.ok(), qPrintable(loaded.ok() ? QString() : loaded.error().toString()));
        QCOMPARE(loaded->mission.routes.size(), size_t(1));
        const mission::Route &route = loaded->mission.routes.front();
        QCOMPARE(route.segments.size(), size_t(kRow + 1));
        const Segment &read = route.segments[size_t(kRow)];
        QCOMPARE(mission::segmentKindName(read), QString::fromLatin1(kind));
        const auto *a = std::get_if<AlgorithmSegment>(&read);
        QVERIFY(a);
        QVERIFY(a->points == figureSegment().points);
        QVERIFY(a->figureParameters == figureSegment().figureParameters);
        QVERIFY(a->parameters == figureSegment().parameters);
        QVERIFY(read == segment());
    }

private slots:
    void initTestCase() { test::useSoftwareRendering(); }

    void init()
    {
        test::ClientWindow::Options options;
        options.vciVehicles = 0;
        m_client = std::make_unique<test::ClientWindow>(options);
        QVERIFY2(m_client->isReady(), qPrintable(m_client->error()));
        window()->requestActivate();
        QVERIFY(QTest::qWaitForWindowActive(window()));
        QVERIFY(m_client->logIn());
        QTRY_COMPARE(window()->property("currentPage").toInt(), 1); // on to the mission
        QVERIFY(m_client->openDemoRoute());
        QTRY_COMPARE(routeLayer()->count(), kRow);
        QTRY_COMPARE(routeLayer()->visibleWaypointCount(), kRow); // fitted to the map
        QVERIFY(test::waitForFrame(window()));
    }

    void cleanup() { m_client.reset(); }

    void circle()
    {
        STEP(draw("CircleAlgorithm", {QPointF(80, 40)}));
        QCOMPARE(mission::segmentKindName(segment()), QStringLiteral("circle"));
        const GeoPoint centre = geoAt(base() + QPointF(80, 40));
        QVERIFY(metersBetween(corner(0), centre) < 0.05);
        QCOMPARE(figureSegment().figureParameters, std::vector<double>{50.0});
        QCOMPARE(areaLayer()->radius(), 50.0);
        // The orbit drawn is at the radius (the planner's points, within centimetres).
        auto orbitRadius = [this, centre] {
            const QGeoCoordinate p = drawnPath().constFirst().value<QGeoCoordinate>();
            return metersBetween(centre, {p.latitude(), p.longitude()});
        };
        QVERIFY2(std::abs(orbitRadius() - 50.0) < 0.3, qPrintable(QString::number(orbitRadius())));

        // The radius handle, dragged 40 px further east: the radius is where it was let go.
        const Segment before = segment();
        STEP(pathCaughtUp());
        const QVariantList pathBefore = drawnPath();
        const int steps = doc()->undoStack()->count();
        const QPointF handle = areaLayer()->radiusHandlePosition();
        QVERIFY(!std::isnan(handle.x()));
        const QPoint from = areaLayer()->mapToScene(handle).toPoint();
        const QPointF centreOnScreen = areaLayer()->mapToScene(onMapItem(centre));
        const double pixelsPer50 = std::hypot(areaLayer()->mapToScene(handle).x() - centreOnScreen.x(),
                                              areaLayer()->mapToScene(handle).y() - centreOnScreen.y());
        const QPoint to = from + QPoint(40, 0);
        const double expected = 50.0 * std::hypot(to.x() - centreOnScreen.x(), to.y() - centreOnScreen.y()) / pixelsPer50;
        drag(from, QPoint(40, 0));
        QTRY_VERIFY2(std::abs(figureSegment().figureParameters.at(0) - expected) < 0.05,
                     qPrintable(QStringLiteral("%1 m, expected %2 m").arg(figureSegment().figureParameters.at(0)).arg(expected)));
        QVERIFY(std::abs(figureSegment().figureParameters.at(0) - metersBetween(centre, geoAt(map()->mapFromScene(to)))) < 0.3);
        QCOMPARE(doc()->undoStack()->count(), steps + 1);
        QTRY_COMPARE(areaLayer()->radius(), figureSegment().figureParameters.at(0));
        QTRY_VERIFY2(std::abs(orbitRadius() - expected) < 0.3, qPrintable(QString::number(orbitRadius())));
        STEP(undoRedo(before, pathBefore));

        // Its radius typed in the editor; then loops: three turns fly three times the points.
        const Segment beforeTyped = segment();
        STEP(pathCaughtUp());
        const QVariantList pathBeforeTyped = drawnPath();
        STEP(type("segment_radius", QStringLiteral("75")));
        QTRY_COMPARE(figureSegment().figureParameters, std::vector<double>{75.0});
        QTRY_COMPARE(areaLayer()->radius(), 75.0);
        QTRY_VERIFY2(std::abs(orbitRadius() - 75.0) < 0.3, qPrintable(QString::number(orbitRadius())));
        STEP(undoRedo(beforeTyped, pathBeforeTyped));
        const int onePass = areaLayer()->transectPointCount();
        QCOMPARE(parameter("loops"), QStringLiteral("1"));
        STEP(typeParameter("loops", QStringLiteral("3")));
        QTRY_VERIFY2(areaLayer()->transectPointCount() > 2 * onePass,
                     qPrintable(QStringLiteral("%1 points, %2 for one loop").arg(areaLayer()->transectPointCount()).arg(onePass)));

        // Its centre moves too.
        STEP(dragVertex(0, QPoint(-30, 25)));
        STEP(saveAndReadBack("circle"));
    }

    void corridor()
    {
        STEP(draw("CorridorMappingAlgorithm", {QPointF(0, 0), QPointF(120, 60), QPointF(260, 20)}));
        QCOMPARE(mission::segmentKindName(segment()), QStringLiteral("corridor"));
        QVERIFY(!areaLayer()->isClosed()); // a line, not an area
        QCOMPARE(areaLayer()->radius(), 0.0);

        STEP(dragVertex(1, QPoint(20, 45)));
        STEP(insertCorner(1));
        STEP(removeCorner(0));
        const QString width = parameter("width");
        QCOMPARE(width, QStringLiteral("30"));
        STEP(typeParameter("width", QStringLiteral("80")));
        STEP(saveAndReadBack("corridor"));
    }

    void perimeter()
    {
        STEP(draw("PerimeterAlgorithm", {QPointF(0, 0), QPointF(160, 0), QPointF(160, 110), QPointF(0, 110)}));
        QCOMPARE(mission::segmentKindName(segment()), QStringLiteral("perimeter"));
        QVERIFY(areaLayer()->isClosed());

        // Corners dragged: the first (under the segment's route marker) and another.
        STEP(dragVertex(0, QPoint(-25, -20)));
        STEP(dragVertex(2, QPoint(60, 20)));

        STEP(insertCorner(0));
        STEP(removeCorner(4));

        // Two loops round the perimeter: twice the points.
        const int oneLoop = areaLayer()->transectPointCount();
        STEP(typeParameter("loops", QStringLiteral("2")));
        QTRY_VERIFY(areaLayer()->transectPointCount() > oneLoop);
        STEP(saveAndReadBack("perimeter"));
    }

    void point()
    {
        STEP(draw("ExpandingSquareAlgorithm", {QPointF(120, 60)}));
        QCOMPARE(mission::segmentKindName(segment()), QStringLiteral("expandingSquare"));
        QCOMPARE(areaLayer()->radius(), 0.0);

        STEP(dragVertex(0, QPoint(-40, 30)));
        // A wider search: a longer square spiral.
        const int before = areaLayer()->transectPointCount();
        QCOMPARE(parameter("searchRadius"), QStringLiteral("350"));
        STEP(typeParameter("searchRadius", QStringLiteral("700")));
        QTRY_VERIFY(areaLayer()->transectPointCount() > before);
        STEP(saveAndReadBack("expandingSquare"));
    }
};

QTEST_MAIN(TestFigureFlows)
#include "tst_figureflows.moc"
