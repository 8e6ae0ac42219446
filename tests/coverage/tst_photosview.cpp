// The replay's Photos… step in the fly view, offscreen (issue 34): a survey's log opened for
// replay, the timeline's Photos… button opens the dialog, the operator's folder placed on the
// chosen vehicle's track with a click; the dialog says how many were placed and what they cover, the
// photo layer draws each photo where the log had the vehicle, a card with a gap shows its hole on
// the map, and the geotagged copies are written where asked.
#include "ClientGraph.h"
#include "MissionController.h"
#include "RouteDocument.h"
#include "GeotagTestSupport.h"
#include "PhotoSurvey.h"
#include "QuickScene.h"
#include "ReplayController.h"
#include "SurveyFlightTestSupport.h"

#include <QDir>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;

class TestPhotosView : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    QString m_log, m_photos, m_gappy;

private slots:
    void initTestCase()
    {
        test::useSoftwareRendering();
        QVERIFY(m_dir.isValid());
        const test::SurveyFlight flight = test::flySurvey();
        QCOMPARE(test::writeSurvey(m_dir.path(), flight), QString());
        m_log = m_dir.filePath(QStringLiteral("survey.sortielog"));
        m_photos = m_dir.filePath(QStringLiteral("card"));
        m_gappy = m_dir.filePath(QStringLiteral("card-with-a-gap"));
    }

    void placeJudgeAndWrite()
    {
        QSettings storage(m_dir.filePath(QStringLiteral("settings.ini")), QSettings::IniFormat);
        client::ClientGraph graph(&storage, {});
        coverage::PhotoSurvey &survey = graph.photos();
        test::QuickScene scene(test::kTelemetryPageQml, QSize(1280, 800), {{QStringLiteral("graph"), QVariant::fromValue(&graph)}});
        QVERIFY2(scene.isReady(), qPrintable(scene.errors()));
        auto *photosButton = scene.find<QQuickItem>(QStringLiteral("photosButton"));
        QVERIFY(photosButton && !photosButton->isVisible()); // nothing replayed, no photos to place

        QVERIFY(graph.replay().open(m_log));
        QTRY_VERIFY(photosButton->isVisible());
        auto *vehicleLayer = scene.find<QQuickItem>(QStringLiteral("vehicleLayer"));
        QVERIFY(vehicleLayer);
        QTRY_COMPARE(vehicleLayer->property("count").toInt(), 1);
        vehicleLayer->setProperty("currentIndex", 0);
        QObject *map = scene.root()->property("map").value<QObject *>();
        QMetaObject::invokeMethod(map, "fitBounds", Q_ARG(double, 56.9495), Q_ARG(double, 24.0995), Q_ARG(double, 56.9525), Q_ARG(double, 24.1030), Q_ARG(qreal, 40));

        // The operator's click on Photos… opens the dialog.
        scene.grab();
        QTest::mouseClick(&scene.view(), Qt::LeftButton, {}, test::sceneCentre(photosButton).toPoint());
        QQuickItem *dialogItem = nullptr;
        QTRY_VERIFY((dialogItem = test::findItem(scene.view().contentItem(), QStringLiteral("placePhotosButton"))) != nullptr);
        auto *folderField = test::findItem(scene.view().contentItem(), QStringLiteral("photoFolderField"));
        QVERIFY(folderField);
        // The folder as typed (the Choose… picker sets the same property).
        folderField->setProperty("text", m_photos);
        QMetaObject::invokeMethod(folderField, "editingFinished");
        QCOMPARE(survey.photoFolder(), m_photos);
        survey.setCamera(test::kSurveyCamera);
        auto *cameraBox = test::findItem(scene.view().contentItem(), QStringLiteral("photoCameraBox"));
        QVERIFY(cameraBox);
        QTRY_COMPARE(cameraBox->property("currentText").toString(), test::kSurveyCamera);

        auto *place = test::findItem(scene.view().contentItem(), QStringLiteral("placePhotosButton"));
        QTRY_VERIFY(place->isEnabled());
        scene.grab();
        QTest::mouseClick(&scene.view(), Qt::LeftButton, {}, test::sceneCentre(place).toPoint());
        QTRY_VERIFY(survey.isBusy() || survey.isMatched());
        QTRY_VERIFY_WITH_TIMEOUT(!survey.isBusy(), 30000);
        QVERIFY2(survey.errorString().isEmpty(), qPrintable(survey.errorString()));
        QCOMPARE(survey.placedCount(), 85);
        auto *summary = test::findItem(scene.view().contentItem(), QStringLiteral("photosSummary"));
        QVERIFY(summary);
        QTRY_COMPARE(summary->property("text").toString(), QStringLiteral("85 of 85 photos placed on EMU-101's track (camera clock 0.0 s)."));
        auto *coverageLabel = test::findItem(scene.view().contentItem(), QStringLiteral("coverageSummary"));
        QVERIFY(coverageLabel);
        const QString judged = coverageLabel->property("text").toString();
        QVERIFY2(judged.startsWith(QStringLiteral("100 % of ")) && judged.contains(QStringLiteral("forward overlap 80 %, side 70 %"))
                     && judged.contains(QStringLiteral("1.64 cm per pixel")),
                 qPrintable(judged));

        // Each photo drawn where the log had the vehicle when it was taken.
        auto *layer = scene.find<QQuickItem>(QStringLiteral("photoLayer"));
        QVERIFY(layer && layer->isVisible());
        QTRY_COMPARE(layer->property("photoCount").toInt(), 85);
        QCOMPARE(layer->property("holeCount").toInt(), 0);
        for (int i : {0, 40, 84}) {
            const geotag::TaggedPhoto &photo = survey.placedPhotos()[size_t(i)];
            QPointF expected, drawn;
            QMetaObject::invokeMethod(map, "fromCoordinate", Q_RETURN_ARG(QPointF, expected),
                                      Q_ARG(QGeoCoordinate, QGeoCoordinate(photo.position.latitude, photo.position.longitude)));
            QMetaObject::invokeMethod(layer, "photoPosition", Q_RETURN_ARG(QPointF, drawn), Q_ARG(int, i));
            QVERIFY2(QLineF(expected, drawn).length() < 1.5, qPrintable(QStringLiteral("photo %1").arg(i)));
        }

        // The copies, where the operator chose (the picker calls the same).
        const QString out = m_dir.filePath(QStringLiteral("tagged"));
        survey.writeCopies(QUrl::fromLocalFile(out).toString());
        QTRY_VERIFY_WITH_TIMEOUT(!survey.isBusy() && !survey.written().isEmpty(), 30000);
        auto *written = test::findItem(scene.view().contentItem(), QStringLiteral("photosWritten"));
        QVERIFY(written);
        QTRY_COMPARE(written->property("text").toString(), QStringLiteral("85 geotagged copies, geo.txt and geotags.csv written to %1.").arg(out));
        QVERIFY(QFile::exists(QDir(out).filePath(QStringLiteral("geo.txt"))));
        const auto gps = test::readGps(QDir(out).filePath(QStringLiteral("DJI_0040.JPG")));
        QVERIFY(gps.latitude && std::fabs(*gps.latitude - survey.placedPhotos()[40].position.latitude) < 1e-6);
        // The photos' own folder is never written into.
        survey.writeCopies(m_photos);
        QTRY_VERIFY(survey.written().contains(QStringLiteral("the originals are never changed")));

        // The card with a gap: its hole listed and shaded where the photos are missing.
        folderField->setProperty("text", m_gappy);
        QMetaObject::invokeMethod(folderField, "editingFinished");
        scene.grab();
        QTest::mouseClick(&scene.view(), Qt::LeftButton, {}, test::sceneCentre(place).toPoint());
        QTRY_VERIFY_WITH_TIMEOUT(survey.isMatched() && !survey.isBusy(), 30000);
        QCOMPARE(survey.placedCount(), 70);
        QVERIFY(survey.holeCount() >= 1);
        QTRY_COMPARE(layer->property("holeCount").toInt(), survey.holeCount());
        auto *holes = test::findItem(scene.view().contentItem(), QStringLiteral("holeList"));
        QVERIFY(holes && holes->isVisible());
        QVERIFY2(survey.holeList().first().contains(QStringLiteral(" m² at 56.95")), qPrintable(survey.holeList().first()));
        QPointF expected, drawn;
        const coverage::Hole &hole = survey.holes().front();
        QMetaObject::invokeMethod(map, "fromCoordinate", Q_RETURN_ARG(QPointF, expected),
                                  Q_ARG(QGeoCoordinate, QGeoCoordinate(hole.centreLatitude, hole.centreLongitude)));
        QMetaObject::invokeMethod(layer, "holePosition", Q_RETURN_ARG(QPointF, drawn), Q_ARG(int, 0));
        QVERIFY(QLineF(expected, drawn).length() < 1.5);

        // Re-fly the gaps: a route of an area scan per hole, open in the mission editor.
        auto *refly = test::findItem(scene.view().contentItem(), QStringLiteral("reflyButton"));
        QVERIFY(refly);
        QTRY_VERIFY(refly->isVisible() && refly->isEnabled());
        scene.grab();
        QTest::mouseClick(&scene.view(), Qt::LeftButton, {}, test::sceneCentre(refly).toPoint());
        QTRY_VERIFY(!survey.reflyText().isEmpty());
        const mission::Route &opened = graph.missions().document()->route();
        QCOMPARE(opened.settings.name, QStringLiteral("Re-fly the gaps"));
        QCOMPARE(int(opened.segments.size()), survey.holeCount());
        const auto *scan = std::get_if<mission::AreaScan>(&opened.segments.front());
        QVERIFY(scan);
        QCOMPARE(scan->parameters.camera.name, test::kSurveyCamera);
        QCOMPARE(scan->parameters.altitude, 60.0);
        QCOMPARE(scan->parameters.frontOverlapPercent, 80.0);
        auto *reflyText = test::findItem(scene.view().contentItem(), QStringLiteral("reflyText"));
        QVERIFY(reflyText);
        QTRY_VERIFY2(reflyText->property("text").toString().startsWith(QStringLiteral("\"Re-fly the gaps\" is open in the mission editor: 1 area scan(s) at 60 m, 80/70 % overlap.")),
                     qPrintable(reflyText->property("text").toString()));

        // Back to live: the replay's photos go with it.
        graph.replay().close();
        QTRY_COMPARE(layer->property("photoCount").toInt(), 0);
        QVERIFY(!survey.isMatched());
    }

    void mistakesAreSaid()
    {
        QSettings storage(m_dir.filePath(QStringLiteral("settings2.ini")), QSettings::IniFormat);
        client::ClientGraph graph(&storage, {});
        coverage::PhotoSurvey &survey = graph.photos();
        survey.setPhotoFolder(m_photos);
        survey.match(0);
        QCOMPARE(survey.errorString(), QStringLiteral("Open the flight's log first."));
        QVERIFY(graph.replay().open(m_log));
        survey.setPhotoFolder(m_dir.filePath(QStringLiteral("no-such-folder")));
        survey.match(0);
        QTRY_VERIFY_WITH_TIMEOUT(!survey.isBusy(), 30000);
        QVERIFY2(survey.errorString().contains(QStringLiteral("no-such-folder")), qPrintable(survey.errorString()));
        survey.setPhotoFolder(m_photos);
        survey.match(5); // the log has one vehicle
        QTRY_VERIFY_WITH_TIMEOUT(!survey.isBusy(), 30000);
        QCOMPARE(survey.errorString(), QStringLiteral("Choose the vehicle that took the photos."));
        // Photos an hour off the log's clock: each named, nothing judged.
        survey.setOffsetSeconds(3600);
        survey.match(0);
        QTRY_VERIFY_WITH_TIMEOUT(!survey.isBusy(), 30000);
        QCOMPARE(survey.placedCount(), 0);
        QCOMPARE(survey.unplaced().size(), 85);
        QVERIFY2(survey.unplaced().first().contains(QStringLiteral("after the track ends")), qPrintable(survey.unplaced().first()));
        QVERIFY2(survey.coverageSummary().startsWith(QStringLiteral("Coverage not judged: no photo has")), qPrintable(survey.coverageSummary()));
        survey.writeCopies(m_dir.filePath(QStringLiteral("none")));
        QCOMPARE(survey.written(), QStringLiteral("No photo is placed: nothing to write."));
        // Back to live while photos are being placed: what arrives afterwards is not shown.
        survey.setOffsetSeconds(0);
        survey.match(0);
        QVERIFY(survey.isBusy());
        graph.replay().close();
        QTRY_VERIFY_WITH_TIMEOUT(!survey.isBusy(), 30000);
        QVERIFY(!survey.isMatched());
        QCOMPARE(survey.placedCount(), 0);
    }
};

QTEST_MAIN(TestPhotosView)
#include "tst_photosview.moc"
