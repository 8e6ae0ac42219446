// The real main window (ClientWindow: the program's graph against the embedded simulator, logged
// in, the demo route open, a VCI vehicle added) drawn in each colour scheme and in German, grabbed
// page by page and judged on the pixels: the ground is the scheme's (its luminance), every text
// shown reads on what is drawn behind it (4.5:1, 7:1 in sunlight), the glance bar is in the
// toolbar, the scheme is switched without a QML warning, and the text checks of VisualCheck hold.
// Each grab is saved (SORTIE_SCREENSHOT_DIR, else beside the binary in themes/).
#include "ClientWindow.h"
#include "Contrast.h"
#include "QuickScene.h"
#include "Theme.h"
#include "VehicleLayer.h"
#include "VisualCheck.h"

#include <QDir>
#include <QHash>
#include <QQmlApplicationEngine>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;
using ui::Theme;

namespace {

QString outputDir()
{
    const QString dir = qEnvironmentVariable("SORTIE_SCREENSHOT_DIR", QStringLiteral(SORTIE_SCREENSHOT_DEFAULT_DIR));
    QDir().mkpath(dir);
    return dir;
}

// The colour most pixels of `rect` have: behind a text, its ground (a glyph covers less than its box).
QColor dominantColour(const QImage &image, const QRect &rect)
{
    QHash<QRgb, int> counts;
    const QRect area = rect.intersected(image.rect());
    for (int y = area.top(); y <= area.bottom(); ++y)
        for (int x = area.left(); x <= area.right(); ++x) {
            ++counts[image.pixel(x, y) | 0xff000000];
        }
    QRgb best = 0;
    int most = -1;
    for (auto it = counts.cbegin(); it != counts.cend(); ++it)
        if (it.value() > most) {
            most = it.value();
            best = it.key();
        }
    return most < 0 ? QColor() : QColor::fromRgb(best);
}

// The product of the opacities from `item` up: a text dimmed on purpose (a stale reading) is not judged.
qreal effectiveOpacity(const QQuickItem *item)
{
    qreal opacity = 1;
    for (; item; item = item->parentItem())
        opacity *= item->opacity();
    return opacity;
}

void collectTexts(QQuickItem *item, QList<QQuickItem *> &texts)
{
    if (!item->isVisible())
        return;
    if ((item->inherits("QQuickText") || item->inherits("QQuickTextInput")) && !item->property("text").toString().trimmed().isEmpty())
        texts << item;
    for (QQuickItem *child : item->childItems())
        collectTexts(child, texts);
}

} // namespace

class TestThemeScreens : public QObject
{
    Q_OBJECT
    std::unique_ptr<test::ClientWindow> m_client;
    QStringList m_qmlWarnings;

    Theme &theme() { return m_client->mainWindow().theme(); }

    // Every text shown in `scope` against the pixels behind it; one line per text that reads poorly.
    QStringList poorContrast(const QImage &image, QQuickItem *scope, double minimum, int *judged)
    {
        QList<QQuickItem *> texts;
        collectTexts(scope, texts);
        QStringList poor;
        const qreal ratio = image.devicePixelRatio();
        for (QQuickItem *text : std::as_const(texts)) {
            if (!text->isEnabled() || effectiveOpacity(text) < 0.99)
                continue; // disabled or dimmed on purpose: WCAG does not ask them to read
            const QColor ink = text->property("color").value<QColor>();
            const QRectF box = text->mapRectToScene(QRectF(0, 0, std::min(text->width(), text->property("contentWidth").toReal() + 2),
                                                           std::min(text->height(), text->property("contentHeight").toReal() + 2)));
            const QRect pixels = QRectF(box.topLeft() * ratio, box.size() * ratio).toAlignedRect();
            if (!ink.isValid() || pixels.width() < 4 || pixels.height() < 4 || !image.rect().intersects(pixels))
                continue;
            const QColor ground = dominantColour(image, pixels.adjusted(-2, -2, 2, 2));
            if (!ground.isValid())
                continue;
            ++*judged;
            const double r = ui::contrast::ratio(ink, ground);
            if (r < minimum)
                poor << QStringLiteral("%1 \"%2\": %3 on %4 is %5:1").arg(text->objectName().isEmpty() ? QString::fromLatin1(text->metaObject()->className()) : text->objectName(),
                                                                       text->property("text").toString().left(40), ink.name(), ground.name())
                            .arg(r, 0, 'f', 2);
        }
        return poor;
    }

    void judge(const QString &name, double minimumContrast)
    {
        QQuickWindow *window = m_client->window();
        QVERIFY(test::waitForFrame(window));
        const QImage image = window->grabWindow();
        QVERIFY2(image.save(QDir(outputDir()).filePath(name + QStringLiteral(".png"))), qPrintable(name));
        const QStringList texts = test::inspectTexts(window->contentItem());
        QVERIFY2(texts.isEmpty(), qPrintable(name + QStringLiteral(":\n  ") + texts.join(QStringLiteral("\n  "))));
        int judged = 0;
        const QStringList poor = poorContrast(image, window->contentItem(), minimumContrast, &judged);
        qInfo().noquote() << name << "texts judged for contrast:" << judged;
        QVERIFY2(judged > 10, qPrintable(name + QStringLiteral(": hardly any text judged (%1 of %2)").arg(judged).arg(test::lastInspectedTextCount())));
        QVERIFY2(poor.isEmpty(), qPrintable(name + QStringLiteral(": words that read poorly:\n  ") + poor.join(QStringLiteral("\n  "))));
    }

private slots:
    void initTestCase()
    {
        test::useSoftwareRendering();
        m_client = std::make_unique<test::ClientWindow>();
        QVERIFY2(m_client->isReady(), qPrintable(m_client->error()));
        // From here on, any QML warning (a binding that breaks when the colours change) fails the test.
        connect(&m_client->mainWindow().engine(), &QQmlEngine::warnings, this, [this](const QList<QQmlError> &warnings) {
            for (const QQmlError &warning : warnings)
                m_qmlWarnings << warning.toString();
        });
        QVERIFY(m_client->logIn());
        QVERIFY(m_client->openDemoRoute());
        QVERIFY(m_client->addVciVehicles());
        m_client->showPage(2);
        auto *layer = m_client->find<ui::VehicleLayer>(QStringLiteral("vehicleLayer"));
        QVERIFY(layer);
        layer->setCurrentIndex(0);
        QTRY_VERIFY_WITH_TIMEOUT(m_client->fleet().vehicleAt(0)->position().isValid(), 10000);
    }

    void cleanupTestCase()
    {
        m_client.reset();
    }

    void cleanup()
    {
        QVERIFY2(m_qmlWarnings.isEmpty(), qPrintable(m_qmlWarnings.join(QLatin1Char('\n'))));
    }

    // The contrast check finds grey words on grey, and leaves dark words on white and dimmed ones alone.
    void theContrastCheckFindsPoorWords()
    {
        const QByteArray qml = R"(
import QtQuick
Rectangle {
    width: 300; height: 200
    color: "#888888"
    Text { objectName: "poor"; x: 10; y: 10; text: "grey on grey"; color: "#777777"; font.pixelSize: 16 }
    Rectangle {
        x: 10; y: 60; width: 200; height: 40; color: "#ffffff"
        Text { objectName: "fine"; x: 4; y: 8; text: "dark on white"; color: "#1a1a1a"; font.pixelSize: 16 }
    }
    Text { objectName: "dimmed"; x: 10; y: 120; opacity: 0.3; text: "dimmed on purpose"; color: "#777777"; font.pixelSize: 16 }
}
)";
        test::QuickScene scene(qml, QSize(300, 200));
        QVERIFY2(scene.isReady(), qPrintable(scene.errors()));
        QVERIFY(test::waitForFrame(&scene.view()));
        int judged = 0;
        const QStringList poor = poorContrast(scene.grab(), scene.root(), 4.5, &judged);
        QCOMPARE(judged, 2);
        QCOMPARE(poor.size(), 1);
        QVERIFY2(poor.constFirst().startsWith(QStringLiteral("poor \"grey on grey\": #777777 on #888888")), qPrintable(poor.constFirst()));
    }

    void eachSchemeAndLanguage_data()
    {
        QTest::addColumn<QString>("scheme");
        QTest::addColumn<QString>("language");
        QTest::newRow("light") << QStringLiteral("light") << QStringLiteral("en");
        QTest::newRow("dark") << QStringLiteral("dark") << QStringLiteral("en");
        QTest::newRow("sunlight") << QStringLiteral("sunlight") << QStringLiteral("en");
        QTest::newRow("light-de") << QStringLiteral("light") << QStringLiteral("de");
        QTest::newRow("sunlight-de") << QStringLiteral("sunlight") << QStringLiteral("de");
    }

    void eachSchemeAndLanguage()
    {
        QFETCH(QString, scheme);
        QFETCH(QString, language);
        m_client->settings().setLanguage(language);
        QTRY_COMPARE(m_client->translations().active(), language);
        m_client->settings().setColourScheme(scheme);
        QCOMPARE(Theme::nameOf(theme().scheme()), scheme);
        const bool dark = scheme != QLatin1String("light");
        QTRY_COMPARE(m_client->window()->property("dark").toBool(), dark);
        const double minimum = scheme == QLatin1String("sunlight") ? 7.0 : 4.5;

        // The login page is mostly the window's ground: it is the scheme's.
        m_client->showPage(0);
        QVERIFY(test::waitForFrame(m_client->window()));
        const QImage login = m_client->window()->grabWindow();
        const QColor ground = dominantColour(login, login.rect());
        QVERIFY2(test::colourDistance(ground.rgb(), theme().window().rgb()) <= 2,
                 qPrintable(QStringLiteral("the ground is %1, the scheme's window %2").arg(ground.name(), theme().window().name())));
        const double luminance = ui::contrast::relativeLuminance(ground);
        if (scheme == QLatin1String("light"))
            QVERIFY2(luminance > 0.8, qPrintable(QString::number(luminance)));
        else if (scheme == QLatin1String("dark"))
            QVERIFY2(luminance < 0.05, qPrintable(QString::number(luminance)));
        else
            QVERIFY2(luminance < 0.005, qPrintable(QString::number(luminance)));

        // The glance bar is in the toolbar, every reading of it shown.
        for (const char *key : {"connection", "vehicle", "gps", "battery", "link"}) {
            auto *text = m_client->find<QQuickItem>(QStringLiteral("glanceText_%1").arg(QLatin1String(key)));
            QVERIFY2(text && text->isVisible() && text->width() > 8, key);
            QVERIFY2(text->mapToScene(QPointF(0, 0)).y() < 40, key);
        }

        const QString suffix = QStringLiteral("-%1-%2").arg(scheme, language);
        for (const auto &[page, name] : {std::pair{0, "login"}, {1, "mission"}, {2, "fly"}}) {
            m_client->showPage(page);
            judge(QString::fromLatin1(name) + suffix, minimum);
            if (QTest::currentTestFailed())
                break;
        }
        m_client->settings().setLanguage(QString());
        m_client->settings().setColourScheme(QStringLiteral("system"));
    }
};

QTEST_MAIN(TestThemeScreens)
#include "tst_themescreens.moc"
