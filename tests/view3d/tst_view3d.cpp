// The 3D view in a real Qt Quick 3D scene (OpenGL, Mesa's llvmpipe under Xvfb): the ground drawn,
// the route in its colour along its projected path, a zone's volume tinting what is behind it, an
// orbit changing the picture, a click selecting the waypoint under it, and no frame while idle.
#include "View3dScene.h"

#include <QSignalSpy>
#include <QTest>

using namespace sortie;
using namespace sortie::test;

namespace {

int distance(QRgb a, const QColor &b)
{
    return std::max({std::abs(qRed(a) - b.red()), std::abs(qGreen(a) - b.green()), std::abs(qBlue(a) - b.blue())});
}

// Pixels of `colour` (within tolerance) in a square of side 2·r+1 around p.
int near(const QImage &image, QPointF p, const QColor &colour, int r = 3, int tolerance = 40)
{
    int n = 0;
    for (int y = int(p.y()) - r; y <= int(p.y()) + r; ++y)
        for (int x = int(p.x()) - r; x <= int(p.x()) + r; ++x)
            if (image.rect().contains(x, y) && distance(image.pixel(x, y), colour) <= tolerance)
                ++n;
    return n;
}

QString glProblem;

} // namespace

class TestView3d : public QObject
{
    Q_OBJECT

    View3dFixture f;
    ui::FlightScene *scene = nullptr;
    const QSize size{800, 600};

    QImage settledGrab()
    {
        scene->waitForBuilds();
        QCoreApplication::processEvents();
        return f.scene->grab();
    }

private slots:
    void initTestCase()
    {
        QVERIFY2(glProblem.isEmpty(), qPrintable(glProblem));
        QVERIFY(f.prepare(1201));
        // West to east over the ridge at 1200 m AMSL.
        mission::Route route;
        route.segments.push_back(waypointAt(46.5, 7.47, 1200.0));
        route.segments.push_back(waypointAt(46.5, 7.50, 1250.0));
        route.segments.push_back(waypointAt(46.5, 7.53, 1200.0));
        f.document.load(route);
        QVERIFY2(f.open(size), qPrintable(f.scene->errors()));
        scene = f.flightScene();
        QVERIFY(scene);
        QTRY_VERIFY(scene->hasScene());
        scene->waitForBuilds();
        QVERIFY(scene->terrainGeometry()->triangleCount() > 1000);
        QVERIFY(!scene->terrainMissing());
        QCOMPARE(scene->waypointCount(), 3);
    }

    void theGroundAndTheRouteAreDrawn()
    {
        const QImage image = settledGrab();
        QVERIFY(!image.isNull());
        image.save(QStringLiteral("view3d-route.png"));
        const QColor clear = f.theme.darkGround() ? QColor(0x1d, 0x27, 0x33) : QColor(0xc9, 0xdc, 0xee);
        // the ground under the view's centre (the camera looks at the route's middle): not the sky
        const QPointF centre(size.width() / 2.0, size.height() * 0.75);
        QVERIFY2(distance(image.pixel(centre.toPoint()), clear) > 30, "the ground is drawn under the route");
        // the route in its colour at each waypoint and half way along each leg
        const QColor route = f.theme.mapPalette().route;
        for (int i = 0; i < scene->waypointCount(); ++i) {
            const QPointF p = scene->toScreen(scene->waypointPosition(i), size.width(), size.height());
            QVERIFY2(near(image, p, route) > 0, qPrintable(QStringLiteral("waypoint %1 at %2,%3").arg(i).arg(p.x()).arg(p.y())));
            if (i + 1 < scene->waypointCount()) {
                const QPointF m = scene->toScreen((scene->waypointPosition(i) + scene->waypointPosition(i + 1)) / 2, size.width(), size.height());
                QVERIFY2(near(image, m, route) > 0, qPrintable(QStringLiteral("leg %1 at %2,%3").arg(i).arg(m.x()).arg(m.y())));
            }
        }
        // ground colour: far from the route, in the lower corner, neither the sky nor the route
        const QRgb corner = image.pixel(40, size.height() - 40);
        QVERIFY(distance(corner, clear) > 30 && distance(corner, route) > 40);
    }

    void aZoneVolumeTintsWhatIsBehindIt()
    {
        const QImage before = settledGrab();
        // an exclusion cylinder from the ground to 1500 m just north of the second waypoint
        airspace::Zone zone;
        zone.name = QStringLiteral("Ridge");
        zone.shape = airspace::ZoneCircle{{46.506, 7.50}, 300.0};
        zone.ceiling = airspace::HeightLimit{1500.0, terrain::HeightReference::Amsl};
        f.airspace->insertCustomZone(0, zone);
        QTRY_VERIFY(scene->zonesGeometry()->triangleCount() > 0);
        const QImage after = settledGrab();
        after.save(QStringLiteral("view3d-zone.png"));
        const QVector3D centre = scene->frame().toScene(std::get<airspace::ZoneCircle>(zone.shape).center, 1400.0);
        const QPointF p = scene->toScreen(centre, size.width(), size.height());
        QVERIFY(QRectF(0, 0, size.width(), size.height()).contains(p));
        const QRgb a = before.pixel(p.toPoint()), b = after.pixel(p.toPoint());
        // redder than before and no longer what was behind it
        QVERIFY2(qRed(b) - qGreen(b) > qRed(a) - qGreen(a) + 20,
                 qPrintable(QStringLiteral("before %1 after %2").arg(QColor(a).name(), QColor(b).name())));
        f.airspace->removeCustomZone(0);
        QTRY_COMPARE(scene->zonesGeometry()->triangleCount(), 0);
    }

    void anOrbitChangesThePicture()
    {
        const QImage before = settledGrab();
        scene->camera()->orbit(150, 40);
        const QImage after = settledGrab();
        after.save(QStringLiteral("view3d-orbit.png"));
        int changed = 0;
        for (int y = 0; y < before.height(); y += 4)
            for (int x = 0; x < before.width(); x += 4)
                if (distance(before.pixel(x, y), QColor(after.pixel(x, y))) > 20)
                    ++changed;
        QVERIFY2(changed > (before.width() / 4) * (before.height() / 4) / 10, qPrintable(QString::number(changed)));
        scene->camera()->orbit(-150, -40);
    }

    void aClickOnAWaypointSelectsIt()
    {
        settledGrab();
        const QPointF p = scene->toScreen(scene->waypointPosition(2), size.width(), size.height());
        QCOMPARE(scene->waypointAt(p.x(), p.y(), size.width(), size.height()), scene->waypointRow(2));
        QTest::mouseClick(&f.scene->view(), Qt::LeftButton, {}, p.toPoint());
        QTRY_COMPARE(f.document.selectedRows(), QList<int>{scene->waypointRow(2)});
        QCOMPARE(scene->waypointAt(5, 5, size.width(), size.height()), -1);
    }

    void anIdleViewDrawsNoFrame()
    {
        settledGrab();
        QSignalSpy frames(&f.scene->view(), &QQuickWindow::frameSwapped);
        // something changes: a frame
        scene->camera()->turn(5);
        QTRY_VERIFY(frames.count() > 0);
        QTest::qWait(200);  // the frame's own follow-ups drawn
        frames.clear();
        // nothing changes for half a second (observed, not waited on): no frame
        QTest::qWait(500);
        QCOMPARE(frames.count(), 0);
    }
};

int main(int argc, char **argv)
{
    useXWithOpenGl();
    QGuiApplication app(argc, argv);
    glProblem = openGlProblem();
    TestView3d test;
    return QTest::qExec(&test, argc, argv);
}

#include "tst_view3d.moc"
