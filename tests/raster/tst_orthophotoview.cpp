// The orthophoto on the map in a real offscreen scene: a MapPane (as the mission and fly views
// have) given a UTM orthophoto with coloured quadrants draws each quadrant where it belongs, above
// the base map and below the page's layers, blended with the chosen opacity; a bad file is refused
// with GDAL's reason, as the map source dialog shows it.
#include "AppSettings.h"
#include "GeoTiffWriter.h"
#include "PasswordVault.h"
#include "MapView.h"
#include "OrthophotoLayer.h"
#include "QuickScene.h"
#include "RasterFileCheck.h"

#include <QDir>
#include <QFileInfo>
#include <QQmlComponent>
#include <QQmlEngine>
#include <QQuickItem>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

#include <array>
#include <cmath>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie::ui;
using namespace sortie::raster::test;
using sortie::test::QuickScene;

namespace {

const QByteArray kScene = R"(
import QtQuick
import Sortie.Ui
Item {
    property alias file: pane.orthophotoFile
    property alias orthoOpacity: pane.orthophotoOpacity
    MapPane {
        id: pane
        objectName: "pane"
        anchors.fill: parent
        units: DisplayUnits {}
        // A page's layer: drawn over the orthophoto.
        Rectangle { objectName: "pageLayer"; x: 20; y: 520; width: 40; height: 40; color: "#ff00ff" }
    }
}
)";

const QColor kQuadrant[4] = {QColor(255, 0, 0), QColor(0, 255, 0), QColor(0, 0, 255), QColor(255, 255, 0)};  // NW, NE, SW, SE

} // namespace

class TestOrthophotoView : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    QString m_file;
    QGeoCoordinate m_quadrantCentre[4];

private slots:
    void initTestCase();
    void quadrantsAreDrawnInPlaceWithTheOpacity();
    void badFileShowsGdalsReason();
    void dialogKeepsTheRastersOrSaysWhyNot();
    void dialogPicksTheRastersWithFileDialogs();
};

void TestOrthophotoView::initTestCase()
{
    sortie::test::useSoftwareRendering();
    // 4 km of UTM 35N around Riga in 20 m pixels, each quadrant one colour.
    OGRSpatialReference wgs84, utm;
    wgs84.importFromEPSG(4326);
    utm.importFromEPSG(32635);
    wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    utm.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    auto *toUtm = OGRCreateCoordinateTransformation(&wgs84, &utm);
    auto *toGeo = OGRCreateCoordinateTransformation(&utm, &wgs84);
    double e = 24.1, n = 56.97;
    toUtm->Transform(1, &e, &n);
    const double e0 = std::floor(e), n0 = std::floor(n);
    for (int q = 0; q < 4; ++q) {
        double x = e0 + (q % 2 == 0 ? 1000 : 3000), y = n0 - (q < 2 ? 1000 : 3000);
        toGeo->Transform(1, &x, &y);
        m_quadrantCentre[q] = QGeoCoordinate(y, x);
    }
    OGRCoordinateTransformation::DestroyCT(toUtm);
    OGRCoordinateTransformation::DestroyCT(toGeo);
    GeoTiffSpec s;
    s.width = s.height = 200;
    const double gt[6] = {e0, 20, 0, n0, 0, -20};
    std::copy(gt, gt + 6, s.geoTransform);
    s.crs = QStringLiteral("EPSG:32635");
    s.bands = 3;
    s.type = GDT_Byte;
    s.tiled = true;
    s.overviews = {2, 4};
    m_file = m_dir.filePath(QStringLiteral("ortho.tif"));
    QVERIFY(writeGeoTiff(m_file, s, [](int b, int r, int c) {
        const QColor colour = kQuadrant[(r < 100 ? 0 : 2) + (c < 100 ? 0 : 1)];
        return double(b == 0 ? colour.red() : b == 1 ? colour.green() : colour.blue());
    }));
}

void TestOrthophotoView::quadrantsAreDrawnInPlaceWithTheOpacity()
{
    QuickScene scene(kScene, QSize(800, 600));
    QVERIFY2(scene.isReady(), qPrintable(scene.errors()));
    auto *map = scene.find<MapView>(QStringLiteral("mapView"));
    auto *layer = scene.find<OrthophotoLayer>(QStringLiteral("orthophotoLayer"));
    QVERIFY(map && layer);
    map->setCenter(QGeoCoordinate(56.952, 24.133));
    map->setZoomLevel(12.5);
    QVERIFY(!layer->isVisible());

    scene.root()->setProperty("file", m_file);
    scene.root()->setProperty("orthoOpacity", 1.0);
    QVERIFY2(layer->isValid(), qPrintable(layer->errorString()));
    QVERIFY(layer->isVisible());
    QTRY_VERIFY(layer->drawnTiles() > 0 && layer->pendingTiles() == 0);
    QTRY_VERIFY(scene.grab().pixel(map->fromCoordinate(m_quadrantCentre[0]).toPoint()) == kQuadrant[0].rgb());
    const QImage opaque = scene.grab();
    for (int q = 0; q < 4; ++q) {
        const QPoint at = map->fromCoordinate(m_quadrantCentre[q]).toPoint();
        QVERIFY2(QRect(0, 0, 800, 600).contains(at), qPrintable(QStringLiteral("quadrant %1 off screen").arg(q)));
        QVERIFY2(sortie::test::colourDistance(opaque.pixel(at), kQuadrant[q].rgb()) <= 2,
                 qPrintable(QStringLiteral("quadrant %1: %2").arg(q).arg(QColor(opaque.pixel(at)).name())));
    }
    // The page's own layer is drawn over the image's layer.
    QCOMPARE(QColor(opaque.pixel(40, 540)), QColor(255, 0, 255));

    // Half opacity: each quadrant half its colour, half the base map's.
    scene.root()->setProperty("orthoOpacity", 0.5);
    QTRY_VERIFY(scene.grab().pixel(map->fromCoordinate(m_quadrantCentre[0]).toPoint()) != kQuadrant[0].rgb());
    const QImage half = scene.grab();

    // No orthophoto: the base map alone. Outside the image (2 km and more west of it) nothing changed.
    scene.root()->setProperty("file", QString());
    QTRY_VERIFY(!layer->isVisible());
    QTRY_VERIFY(scene.grab().pixel(map->fromCoordinate(m_quadrantCentre[0]).toPoint()) != half.pixel(map->fromCoordinate(m_quadrantCentre[0]).toPoint()));
    const QImage without = scene.grab();
    if (qEnvironmentVariableIsSet("SORTIE_SAVE_GRABS"))
        without.save(QStringLiteral("/tmp/ortho-without.png")), opaque.save(QStringLiteral("/tmp/ortho-opaque.png")), half.save(QStringLiteral("/tmp/ortho-half.png"));
    QVERIFY(map->toCoordinate(QPointF(100, 300)).longitude() < m_quadrantCentre[0].longitude() - 0.03);
    QCOMPARE(opaque.pixel(100, 300), without.pixel(100, 300));
    QCOMPARE(half.pixel(100, 300), without.pixel(100, 300));
    for (int q = 0; q < 4; ++q) {
        const QPoint at = map->fromCoordinate(m_quadrantCentre[q]).toPoint();
        const QColor base(without.pixel(at)), colour = kQuadrant[q], got(half.pixel(at));
        const QColor expected((base.red() + colour.red()) / 2, (base.green() + colour.green()) / 2, (base.blue() + colour.blue()) / 2);
        QVERIFY2(sortie::test::colourDistance(got.rgb(), expected.rgb()) <= 4,
                 qPrintable(QStringLiteral("quadrant %1: %2, expected %3").arg(q).arg(got.name(), expected.name())));
    }
}

void TestOrthophotoView::badFileShowsGdalsReason()
{
    const QString bad = m_dir.filePath(QStringLiteral("bad.tif"));
    QFile f(bad);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("no image in here");
    f.close();
    RasterFileCheck check;
    QVERIFY(check.orthophotoProblem(m_file).isEmpty());
    QVERIFY(check.orthophotoProblem(QString()).isEmpty());
    const QString problem = check.orthophotoProblem(QUrl::fromLocalFile(bad).toString());
    QVERIFY2(problem.startsWith(bad + QLatin1String(": ")) && problem.size() > bad.size() + 10, qPrintable(problem));
    QVERIFY(check.checkDem(bad).problem.startsWith(bad + QLatin1String(": ")));
    QVERIFY(check.checkDem(bad).leftOut.isEmpty());

    QuickScene scene(kScene, QSize(400, 300));
    QVERIFY2(scene.isReady(), qPrintable(scene.errors()));
    scene.root()->setProperty("file", bad);
    auto *layer = scene.find<OrthophotoLayer>(QStringLiteral("orthophotoLayer"));
    QVERIFY(!layer->isValid());
    QVERIFY(!layer->isVisible());
    QVERIFY(layer->errorString().startsWith(bad));
}

void TestOrthophotoView::dialogKeepsTheRastersOrSaysWhyNot()
{
    QSettings storage(m_dir.filePath(QStringLiteral("sortie.ini")), QSettings::IniFormat);
    sortie::secrets::PasswordVault vault(QStringLiteral("sortie-tests"));
    AppSettings settings(&storage, &vault);
    QCOMPARE(settings.orthophotoOpacity(), 0.8);
    QuickScene scene(R"(
import QtQuick
import Sortie.Ui
Item {
    id: root
    required property AppSettings appSettings
    MapSourceDialog { objectName: "dialog"; appSettings: root.appSettings }
}
)", QSize(800, 760), {{QStringLiteral("appSettings"), QVariant::fromValue(&settings)}});
    QVERIFY2(scene.isReady(), qPrintable(scene.errors()));
    QObject *dialog = scene.find(QStringLiteral("dialog"));
    QVERIFY(dialog);
    QMetaObject::invokeMethod(dialog, "open");
    QTRY_VERIFY(dialog->property("opened").toBool());
    QObject *orthophoto = scene.find(QStringLiteral("orthophotoField"));
    QObject *dem = scene.find(QStringLiteral("demField"));
    QObject *problem = scene.find(QStringLiteral("orthophotoProblem"));
    QObject *opacity = scene.find(QStringLiteral("orthophotoOpacity"));
    QVERIFY(orthophoto && dem && problem && opacity);

    // A file GDAL cannot read: its reason under the field, and OK waits.
    const QString bad = m_dir.filePath(QStringLiteral("garbage.tif"));
    QFile f(bad);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("garbage");
    f.close();
    orthophoto->setProperty("text", bad);
    QVERIFY2(problem->property("text").toString().startsWith(bad + QLatin1String(": ")), qPrintable(problem->property("text").toString()));
    QVERIFY(!dialog->property("rastersUsable").toBool());
    dem->setProperty("text", bad);
    QVERIFY(scene.find(QStringLiteral("demProblem"))->property("text").toString().startsWith(bad));

    // A folder with a bad file among good ones: usable, and the bad file is named with its reason.
    GeoTiffSpec tile;
    tile.width = tile.height = 4;
    const double tileGt[6] = {24.0, 0.1, 0, 57.0, 0, -0.1};
    std::copy(tileGt, tileGt + 6, tile.geoTransform);
    const QString folder = m_dir.filePath(QStringLiteral("dem-with-a-bad-file"));
    QVERIFY(QDir().mkpath(folder));
    QVERIFY(writeGeoTiff(folder + QStringLiteral("/good.tif"), tile, [](int, int, int) { return 12.0; }));
    QVERIFY(QFile::copy(bad, folder + QStringLiteral("/broken.tif")));
    QObject *leftOut = scene.find(QStringLiteral("demLeftOut"));
    QVERIFY(leftOut);
    QVERIFY(!leftOut->property("visible").toBool());
    orthophoto->setProperty("text", QString());
    dem->setProperty("text", folder);
    QVERIFY2(dialog->property("rastersUsable").toBool(), qPrintable(scene.find(QStringLiteral("demProblem"))->property("text").toString()));
    const QString named = leftOut->property("text").toString();
    QVERIFY2(named.startsWith(QLatin1String("1 file")) && named.contains(folder + QStringLiteral("/broken.tif: ")), qPrintable(named));
    QVERIFY(named.size() > named.indexOf(QLatin1String("broken.tif: ")) + 20);  // GDAL's reason follows
    QVERIFY(leftOut->property("visible").toBool());

    // Usable files: kept in the settings with the opacity.
    GeoTiffSpec s;
    s.width = s.height = 4;
    const double gt[6] = {24.0, 0.1, 0, 57.0, 0, -0.1};
    std::copy(gt, gt + 6, s.geoTransform);
    const QString demFile = m_dir.filePath(QStringLiteral("dem.tif"));
    QVERIFY(writeGeoTiff(demFile, s, [](int, int, int) { return 12.0; }));
    orthophoto->setProperty("text", m_file);
    dem->setProperty("text", demFile);
    opacity->setProperty("value", 0.5);
    QVERIFY(dialog->property("rastersUsable").toBool());
    QVERIFY(problem->property("text").toString().isEmpty());
    QMetaObject::invokeMethod(dialog, "accept");
    QCOMPARE(settings.orthophotoFile(), m_file);
    QCOMPARE(settings.demPath(), demFile);
    QCOMPARE(settings.orthophotoOpacity(), 0.5);
    QCOMPARE(storage.value(QStringLiteral("terrain/demFolder")).toString(), demFile);  // what the terrain reads at start
}

namespace {
// An item by object name among `item`'s visual children (a popup's items are not its QObject children).
QQuickItem *visualChild(QQuickItem *item, const QString &name)
{
    for (QQuickItem *child : item->childItems()) {
        if (child->objectName() == name)
            return child;
        if (QQuickItem *found = visualChild(child, name))
            return found;
    }
    return nullptr;
}
} // namespace

// The Browse buttons open Qt Quick's file and folder dialogs (the non-native ones offscreen); what is
// accepted there lands in the field as a local path and is checked like a typed one.
void TestOrthophotoView::dialogPicksTheRastersWithFileDialogs()
{
    QSettings storage(m_dir.filePath(QStringLiteral("picker.ini")), QSettings::IniFormat);
    sortie::secrets::PasswordVault vault(QStringLiteral("sortie-tests"));
    AppSettings settings(&storage, &vault);
    QuickScene scene(R"(
import QtQuick
import Sortie.Ui
Item {
    id: root
    required property AppSettings appSettings
    MapSourceDialog { objectName: "dialog"; appSettings: root.appSettings }
}
)", QSize(800, 760), {{QStringLiteral("appSettings"), QVariant::fromValue(&settings)}});
    QVERIFY2(scene.isReady(), qPrintable(scene.errors()));
    QObject *dialog = scene.find(QStringLiteral("dialog"));
    QVERIFY(dialog);
    QMetaObject::invokeMethod(dialog, "open");
    QTRY_VERIFY(dialog->property("opened").toBool());

    for (const char *name : {"orthophotoBrowse", "orthophotoPicker", "demFileBrowse", "demFilePicker", "demFolderBrowse", "demFolderPicker"})
        QVERIFY2(scene.find(QString::fromLatin1(name)), name);
    // Qt Quick's own dialogs need Qt.labs.folderlistmodel; without it Qt 6.4 crashes on open().
    QQmlEngine probe;
    QQmlComponent folderList(&probe);
    folderList.setData("import Qt.labs.folderlistmodel\nFolderListModel {}", QUrl());
    QVERIFY2(!folderList.isError(),
             "qml6-module-qt-labs-folderlistmodel is not installed (scripts/install-deps.sh installs it): the file dialogs cannot be opened");

    struct Case
    {
        const char *button, *picker, *field, *selection;
        QString chosen;
    };
    // A folder of one raster, alone in its parent (the folder dialog lists the parent).
    const QString demFolder = m_dir.filePath(QStringLiteral("picked/dem"));
    QVERIFY(QDir().mkpath(demFolder));
    QVERIFY(QFile::copy(m_file, demFolder + QStringLiteral("/tile.tif")));
    const Case cases[] = {
        {"orthophotoBrowse", "orthophotoPicker", "orthophotoField", "selectedFile", m_file},
        {"demFileBrowse", "demFilePicker", "demField", "selectedFile", m_file},
        {"demFolderBrowse", "demFolderPicker", "demField", "selectedFolder", demFolder},
    };
    for (const Case &c : cases) {
        QObject *button = scene.find(QString::fromLatin1(c.button));
        QObject *picker = scene.find(QString::fromLatin1(c.picker));
        QVERIFY2(button && picker, c.button);
        QVERIFY(!picker->property("visible").toBool());
        QVERIFY(picker->setProperty("currentFolder", QUrl::fromLocalFile(QFileInfo(c.chosen).path())));
        QVERIFY(QMetaObject::invokeMethod(button, "clicked"));
        QTRY_VERIFY2(picker->property("visible").toBool(), c.picker);
        // Qt Quick's dialog lists the folder in the background: the chosen entry is picked in the list,
        // as a click on it does (it becomes the list's current item).
        const bool folders = QLatin1String(c.selection) == QLatin1String("selectedFolder");
        // The listing may still show the previous case's folder: wait for the chosen entry itself.
        const QString delegateName = folders ? QStringLiteral("folderDialogDelegate%1") : QStringLiteral("fileDialogDelegate%1");
        const QUrl chosenUrl = QUrl::fromLocalFile(c.chosen);
        QQuickItem *chosenEntry = nullptr;
        const auto findChosen = [&] {
            QQuickItem *view = visualChild(scene.view().contentItem(), folders ? QStringLiteral("folderDialogListView") : QStringLiteral("fileDialogListView"));
            for (int i = 0; view && i < view->property("count").toInt() && !chosenEntry; ++i)
                if (QQuickItem *entry = visualChild(view, delegateName.arg(i)); entry && entry->property("file").toUrl() == chosenUrl)
                    chosenEntry = entry;
            return chosenEntry != nullptr;
        };
        QTRY_VERIFY2(findChosen(), qPrintable(c.chosen));
        QVERIFY(QMetaObject::invokeMethod(chosenEntry, "clicked"));
        QVERIFY(QMetaObject::invokeMethod(picker, "accept"));
        QTRY_VERIFY(!picker->property("visible").toBool());
        QCOMPARE(scene.find(QString::fromLatin1(c.field))->property("text").toString(), c.chosen);
    }
    // A folder of rasters is a usable DEM; the picked paths are kept on OK.
    QVERIFY2(dialog->property("rastersUsable").toBool(), qPrintable(scene.find(QStringLiteral("demProblem"))->property("text").toString()));
    QMetaObject::invokeMethod(dialog, "accept");
    QCOMPARE(settings.orthophotoFile(), m_file);
    QCOMPARE(settings.demPath(), demFolder);
}

QTEST_MAIN(TestOrthophotoView)
#include "tst_orthophotoview.moc"
