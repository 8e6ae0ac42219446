// The main pages (login, mission, fly) in the longest language: no text clipped, past its frame or
// over another (VisualCheck, as tst_visualquality judges English). The longest language is made
// here: a pseudo-translation that lengthens every word by 40 % (German, the longest of the three,
// runs some 30 % over English), installed above Sortie's translators so that every context, Qt's
// included, is lengthened. When the real German has landed it is judged too. The renderings are
// saved beside the test's binary (longest/).
// What VisualCheck does not judge, and the pseudo renderings show: a text cut at the side by a
// clipping panel, and a frame's content running past the frame's border (the login frame's title
// and "remember" box are checked here: the frame grows with its words; and the waypoint table's
// headers, which widen their columns rather than elide). The mission panel's
// bulk-edit fields flow on to a second line, so its Upload button stays inside in German.
#include "ClientWindow.h"
#include "QuickScene.h"
#include "VehicleLayer.h"
#include "VisualCheck.h"

#include <QDir>
#include <QFile>
#include <QQmlEngine>
#include <QQuickItem>
#include <QRegularExpression>
#include <QTest>
#include <QTranslator>
#include <QtQml/qqmlextensionplugin.h>

#include <cmath>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;

namespace {

// Every word 40 % longer ("Login" -> "LoginLo"); placeholders (%1, %n, %L1), tags and entities kept.
class PseudoTranslator : public QTranslator
{
public:
    static QString lengthen(const QString &source)
    {
        static const QRegularExpression parts(QStringLiteral("(<[^>]*>|&\\w+;|%L?\\d+|%n)|([^\\W\\d_]+)"));
        QString out;
        qsizetype at = 0;
        for (auto m = parts.globalMatch(source); m.hasNext();) {
            const auto match = m.next();
            out += source.mid(at, match.capturedStart() - at);
            out += match.captured(0);
            if (match.hasCaptured(2)) {
                const QString word = match.captured(2);
                out += word.left(qsizetype(std::ceil(word.size() * 0.4)));
            }
            at = match.capturedEnd();
        }
        return out + source.mid(at);
    }

    bool isEmpty() const override { return false; }
    QString translate(const char *, const char *source, const char *, int) const override
    {
        return lengthen(QString::fromUtf8(source));
    }
};

QString outputDir()
{
    const QString dir = QStringLiteral(SORTIE_LONGEST_DIR);
    QDir().mkpath(dir);
    return dir;
}

// A Repeater's items are found through the item tree, not the object tree.
QQuickItem *findItem(QQuickItem *scope, const QString &name)
{
    if (scope->objectName() == name)
        return scope;
    for (QQuickItem *child : scope->childItems())
        if (QQuickItem *found = findItem(child, name))
            return found;
    return nullptr;
}

} // namespace

class TestLongestLanguage : public QObject
{
    Q_OBJECT

    std::unique_ptr<test::ClientWindow> m_client;
    PseudoTranslator m_pseudo;

    // VisualCheck knows a popup's frame, not a Frame's: the login frame's title and "remember" box
    // are checked against its border here.
    void loginFrameHoldsItsWords(const QString &file)
    {
        auto *frame = m_client->find<QQuickItem>(QStringLiteral("loginFrame"));
        QVERIFY(frame);
        const QRectF inside = frame->mapRectToScene(QRectF(0, 0, frame->width(), frame->height()));
        for (const char *name : {"loginTitle", "rememberCheck"}) {
            auto *item = m_client->find<QQuickItem>(QString::fromLatin1(name));
            QVERIFY(item);
            // What its words need: a label's widest line (it wraps), a check box's whole text (it elides).
            const bool wraps = qstrcmp(name, "loginTitle") == 0;
            const qreal needed = wraps ? item->property("contentWidth").toReal() : item->implicitWidth();
            const QRectF at = item->mapRectToScene(QRectF(0, 0, std::max(needed, item->width()), item->height()));
            QVERIFY2(inside.contains(at) && needed <= item->width() + 0.5,
                     qPrintable(QStringLiteral("%1: %2 needs %3 px, has %4, at %5..%6 in a frame %7..%8")
                                    .arg(file, QString::fromLatin1(name)).arg(needed).arg(item->width())
                                    .arg(at.left()).arg(at.right()).arg(inside.left()).arg(inside.right())));
        }
    }

    void judgeThePages(const QString &language)
    {
        QQuickWindow *window = m_client->window();
        qmlEngine(window)->retranslate(); // what Translations does on a change of language
        for (const auto &[page, name] : {std::pair{0, "login"}, {1, "mission"}, {2, "fly"}}) {
            m_client->showPage(page);
            QVERIFY(test::waitForFrame(window));
            const QStringList problems = test::inspectTexts(window->contentItem());
            const QString file = QDir(outputDir()).filePath(language + QLatin1Char('-') + QString::fromLatin1(name) + QStringLiteral(".png"));
            window->grabWindow().save(file);
            QVERIFY2(test::lastInspectedTextCount() > 3, qPrintable(file + QStringLiteral(": hardly any text seen")));
            QVERIFY2(problems.isEmpty(), qPrintable(file + QStringLiteral(":\n  ") + problems.join(QStringLiteral("\n  "))));
            if (page == 0)
                loginFrameHoldsItsWords(file);
            if (page == 1)
                waypointHeadersShowWhole(file);
        }
    }

    // VisualCheck accepts an elided text; the waypoint table's headers are not to be elided: the
    // columns widen to their words, and the panel beside the map to its table.
    void waypointHeadersShowWhole(const QString &file)
    {
        for (int column = 0; column < 8; ++column) {
            const QString name = QStringLiteral("waypointHeader_%1").arg(column);
            QQuickItem *header = findItem(m_client->window()->contentItem(), name);
            QVERIFY2(header, qPrintable(name));
            QVERIFY2(!header->property("truncated").toBool(),
                     qPrintable(QStringLiteral("%1: the header \"%2\" is cut to %3 px")
                                    .arg(file, header->property("text").toString()).arg(header->width())));
        }
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
        // A vehicle chosen, so the instruments show values rather than dashes.
        m_client->showPage(2);
        auto *layer = m_client->find<ui::VehicleLayer>(QStringLiteral("vehicleLayer"));
        QVERIFY(layer);
        layer->setCurrentIndex(0);
        QTRY_VERIFY_WITH_TIMEOUT(m_client->fleet().vehicleAt(0)->position().isValid(), 10000);
    }

    void cleanupTestCase() { m_client.reset(); }

    void thePseudoTranslationLengthens()
    {
        QCOMPARE(PseudoTranslator::lengthen(QStringLiteral("Login")), QStringLiteral("LoginLo"));
        QCOMPARE(PseudoTranslator::lengthen(QStringLiteral("%n zone(s) at %1")), QStringLiteral("%n zonezo(ss) ata %1"));
        QCOMPARE(PseudoTranslator::lengthen(QStringLiteral("<b>Go</b>")), QStringLiteral("<b>GoG</b>"));
    }

    void pseudoLongest()
    {
        QCoreApplication::installTranslator(&m_pseudo);
        judgeThePages(QStringLiteral("pseudo"));
        QCoreApplication::removeTranslator(&m_pseudo);
    }

    void german()
    {
        if (!QFile::exists(QStringLiteral(":/i18n/sortie_de.qm")))
            QFAIL("no German compiled into the program (:/i18n/sortie_de.qm): resources/i18n/sortie_de.ts is missing or was not built");
        m_client->settings().setLanguage(QStringLiteral("de"));
        QTRY_COMPARE(m_client->translations().active(), QStringLiteral("de"));
        judgeThePages(QStringLiteral("de"));
        m_client->settings().setLanguage(QString());
    }
};

QTEST_MAIN(TestLongestLanguage)
#include "tst_longestlanguage.moc"
