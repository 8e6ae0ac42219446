// Visual quality: every page and dialog of the real client, against the embedded simulator (the
// demo route open, HCI and VCI vehicles flying), rendered offscreen at 1280×800 and 1920×1080 in
// a light and a dark palette; no text may be clipped, run past its frame, overlap another text or
// fall back to a missing glyph (VisualCheck). Each rendering is saved beside the test's binary.
#include "ClientWindow.h"
#include "QuickScene.h"
#include "VehicleLayer.h"
#include "VisualCheck.h"

#include <QDir>
#include <QGuiApplication>
#include <QPalette>
#include <QSignalSpy>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;

namespace {


QString outputDir()
{
    const QString dir = qEnvironmentVariable("SORTIE_QUALITY_DIR", QStringLiteral(SORTIE_QUALITY_DEFAULT_DIR));
    QDir().mkpath(dir);
    return dir;
}

// The controls laid on the maps of the mission and fly pages.
const QStringList kMapControls = {QStringLiteral("zoomButtons"), QStringLiteral("scaleBarFrame"), QStringLiteral("attributionLabel"),
                                  QStringLiteral("flyMapControls")};

} // namespace

class TestVisualQuality : public QObject
{
    Q_OBJECT

    std::unique_ptr<test::ClientWindow> m_client;

    void check(const QString &name, QQuickItem *scope)
    {
        QVERIFY(test::waitForFrame(m_client->window()));
        const QStringList problems = test::inspectTexts(scope);
        QVERIFY2(test::lastInspectedTextCount() > 3, qPrintable(name + QStringLiteral(": hardly any text seen")));
        m_client->window()->grabWindow().save(QDir(outputDir()).filePath(name + QStringLiteral(".png")));
        QVERIFY2(problems.isEmpty(), qPrintable(name + QStringLiteral(":\n  ") + problems.join(QStringLiteral("\n  "))));
    }

    QQuickItem *popupItem(const char *name)
    {
        QObject *popup = m_client->find<QObject>(QString::fromLatin1(name));
        if (!popup)
            return nullptr;
        auto *content = popup->property("contentItem").value<QQuickItem *>();
        return content ? content->parentItem() : nullptr;
    }

    void openPopup(const char *name)
    {
        QObject *popup = m_client->find<QObject>(QString::fromLatin1(name));
        QVERIFY2(popup, name);
        QMetaObject::invokeMethod(popup, "open");
        QTRY_VERIFY(popup->property("opened").toBool());
    }

    void closePopup(const char *name)
    {
        QObject *popup = m_client->find<QObject>(QString::fromLatin1(name));
        QMetaObject::invokeMethod(popup, "close");
        QTRY_VERIFY(!popup->property("visible").toBool());
    }

private slots:
    void initTestCase()
    {
        test::useSoftwareRendering();
        m_client = std::make_unique<test::ClientWindow>();
        QVERIFY2(m_client->isReady(), qPrintable(m_client->error()));
        QVERIFY(m_client->logIn());
        QVERIFY(m_client->openDemoRoute());
        QVERIFY(m_client->addVciVehicles());
        QTRY_COMPARE_WITH_TIMEOUT(m_client->fleet().count(), 4, 10000);
        // A vehicle chosen, so the instruments show values rather than dashes.
        m_client->showPage(2);
        auto *layer = m_client->find<ui::VehicleLayer>(QStringLiteral("vehicleLayer"));
        QVERIFY(layer);
        layer->setCurrentIndex(0);
        QTRY_VERIFY_WITH_TIMEOUT(m_client->fleet().vehicleAt(0)->position().isValid(), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(std::isfinite(m_client->fleet().vehicleAt(0)->batteryVoltage()), 10000);
    }

    void cleanupTestCase()
    {
        m_client.reset();
        QGuiApplication::setPalette(QPalette());
    }

    // The map check finds a control moved back over the labels (where "Fit all" used to sit).
    void theMapCheckFindsACoveredLabel()
    {
        m_client->showPage(2);
        auto *pane = m_client->page("telemetryPage")->property("pane").value<QQuickItem *>();
        QVERIFY(pane);
        QVERIFY(test::waitForFrame(m_client->window()));
        QVERIFY(test::inspectMapControls(pane, kMapControls).isEmpty());
        auto *row = pane->findChild<QQuickItem *>(QStringLiteral("flyMapControls"));
        QVERIFY(row);
        QObject *anchors = row->property("anchors").value<QObject *>();
        const QVariant top = anchors->property("topMargin"), left = anchors->property("leftMargin");
        anchors->setProperty("topMargin", 10);
        anchors->setProperty("leftMargin", 10);
        const QString found = test::inspectMapControls(pane, kMapControls).join(QLatin1Char('\n'));
        anchors->setProperty("topMargin", top);
        anchors->setProperty("leftMargin", left);
        QVERIFY2(found.contains(QStringLiteral("flyMapControls reaches into the graticule's label band")), qPrintable(found));
        // Two controls on top of each other.
        auto *zoom = pane->findChild<QQuickItem *>(QStringLiteral("zoomButtons"));
        QVERIFY(zoom);
        const QPointF at = zoom->mapToItem(row->parentItem(), QPointF(0, 0));
        anchors->setProperty("leftMargin", at.x());
        const QString crossing = test::inspectMapControls(pane, kMapControls).join(QLatin1Char('\n'));
        anchors->setProperty("leftMargin", left);
        QVERIFY2(crossing.contains(QStringLiteral("flyMapControls and zoomButtons cover each other"))
                     || crossing.contains(QStringLiteral("zoomButtons and flyMapControls cover each other")), qPrintable(crossing));
    }

    // The checker itself finds each fault on purpose-made texts, and leaves an elided one alone.
    void theCheckerFindsEachFault()
    {
        const QByteArray qml = R"(
import QtQuick
Item {
    width: 400; height: 300
    Text { objectName: "clipped"; y: 0; width: 40; text: "SpeedActions" }
    Text { objectName: "one"; y: 40; text: "overlapping one" }
    Text { objectName: "two"; x: 30; y: 45; text: "overlapping two" }
    Text { objectName: "glyph"; y: 100 }
    Text { objectName: "elided"; y: 150; width: 40; elide: Text.ElideRight; text: "elided on purpose" }
    Text { objectName: "wide"; x: 350; y: 200; text: "past the edge of the window" }
}
)";
        test::QuickScene scene(qml, QSize(400, 300));
        QVERIFY2(scene.isReady(), qPrintable(scene.errors()));
        const char32_t unassigned = 0x10FFFD; // a private-use code point no font draws
        scene.find(QStringLiteral("glyph"))->setProperty("text", QStringLiteral("a ") + QString::fromUcs4(&unassigned, 1));
        QVERIFY(test::waitForFrame(&scene.view()));
        const QString found = test::inspectTexts(scene.root()).join(QLatin1Char('\n'));
        QVERIFY2(found.contains(QStringLiteral("clipped: “SpeedActions”")), qPrintable(found));
        QVERIFY2(found.contains(QStringLiteral("overlapping: “overlapping one” (in one) and “overlapping two” (in two)")), qPrintable(found));
        QVERIFY2(found.contains(QStringLiteral("missing glyph U+10fffd")), qPrintable(found));
        QVERIFY2(found.contains(QStringLiteral("out of the window: “past the edge of the window”")), qPrintable(found));
        QVERIFY2(!found.contains(QStringLiteral("elided on purpose")), qPrintable(found));
    }

    void everyViewAndDialog_data()
    {
        QTest::addColumn<QSize>("size");
        QTest::addColumn<bool>("dark");
        for (const QSize size : {QSize(1280, 800), QSize(1920, 1080)})
            for (bool dark : {false, true})
                QTest::addRow("%dx%d-%s", size.width(), size.height(), dark ? "dark" : "light") << size << dark;
    }

    void everyViewAndDialog()
    {
        QFETCH(QSize, size);
        QFETCH(bool, dark);
        QGuiApplication::setPalette(dark ? sortie::test::darkPalette() : QPalette());
        QQuickWindow *window = m_client->window();
        window->resize(size);
        QTRY_COMPARE(window->size(), size);
        QTRY_COMPARE(window->property("dark").toBool(), dark);
        const QString suffix = QStringLiteral("-%1x%2-%3").arg(size.width()).arg(size.height()).arg(dark ? "dark" : "light");

        for (const auto &[page, name] : {std::pair{0, "login"}, {1, "mission"}, {2, "fly"}}) {
            m_client->showPage(page);
            check(QString::fromLatin1(name) + suffix, window->contentItem());
            if (QTest::currentTestFailed())
                return;
        }
        // No control on a map covers a graticule label or another control.
        for (const char *pageName : {"missionPage", "telemetryPage"}) {
            auto *pane = m_client->page(pageName)->property("pane").value<QQuickItem *>();
            QVERIFY2(pane, pageName);
            const QStringList problems = test::inspectMapControls(pane, kMapControls);
            QVERIFY2(problems.isEmpty(), qPrintable(QString::fromLatin1(pageName) + suffix + QStringLiteral(":\n  ") + problems.join(QStringLiteral("\n  "))));
        }

        m_client->showPage(2);
        for (const char *dialog : {"shortcutHelp", "mapSourceDialog"}) {
            openPopup(dialog);
            check(QString::fromLatin1(dialog) + suffix, popupItem(dialog));
            closePopup(dialog);
            if (QTest::currentTestFailed())
                return;
        }
        QObject *confirm = m_client->find<QObject>(QStringLiteral("commandConfirmDialog"));
        QVERIFY(confirm);
        confirm->setProperty("text", QStringLiteral("Take off with EMU-101 to 10 m?"));
        openPopup("commandConfirmDialog");
        check(QStringLiteral("confirm") + suffix, popupItem("commandConfirmDialog"));
        closePopup("commandConfirmDialog");
    }
};

QTEST_MAIN(TestVisualQuality)
#include "tst_visualquality.moc"
