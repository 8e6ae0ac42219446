// The language chosen at runtime, without a restart: the whole client (ClientWindow, the program's
// wiring) against the embedded simulator. The header's selector lists the languages by their own
// names; choosing one re-words the tabs and re-formats the numbers (a German decimal comma in the
// fly view's altitude). The words come from a small German .ts of the tests' own (tests/i18n/data); the
// real German (resources/i18n/sortie_de.ts, compiled into the program) is checked when it is there.
#include "ClientWindow.h"
#include "DisplayUnits.h"
#include "QuickScene.h"
#include "RouteEndurance.h"
#include "Translations.h"
#include "VehicleLayer.h"

#include <QFile>
#include <QLibraryInfo>
#include <QQmlContext>
#include <QQmlExpression>
#include <QQuickItem>
#include <QLocale>
#include <QRegularExpression>
#include <QTest>
#include <QTranslator>
#include <QtQml/qqmlextensionplugin.h>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;

namespace {

QString textOf(test::ClientWindow &client, const char *name)
{
    QObject *item = client.find<QObject>(QString::fromLatin1(name));
    return item ? item->property("text").toString() : QStringLiteral("<no %1>").arg(QString::fromLatin1(name));
}

// Every text shown under an item (a list's rows: delegates are its visual children).
QStringList textsUnder(QObject *root)
{
    QStringList texts;
    auto *item = qobject_cast<QQuickItem *>(root);
    if (!item)
        return texts;
    for (QQuickItem *child : item->childItems()) {
        if (const QVariant text = child->property("text"); text.isValid() && !text.toString().isEmpty())
            texts << text.toString();
        texts << textsUnder(child);
    }
    return texts;
}

// The text of a dialog's standard button, as the dialog's own QML reads it.
QString standardButtonText(QObject *dialog, const char *button)
{
    if (!dialog)
        return QStringLiteral("<no dialog>");
    QQmlExpression expression(qmlContext(dialog), dialog, QStringLiteral("footer.standardButton(Dialog.%1).text").arg(QLatin1String(button)));
    const QVariant text = expression.evaluate();
    return expression.hasError() ? expression.error().toString() : text.toString();
}


} // namespace

class TestTranslations : public QObject
{
    Q_OBJECT

    std::unique_ptr<test::ClientWindow> m_client;

private slots:
    void initTestCase()
    {
        test::useSoftwareRendering();
        test::ClientWindow::Options options;
        options.translationsFolder = QStringLiteral(SORTIE_TEST_TRANSLATIONS);
        m_client = std::make_unique<test::ClientWindow>(options);
        QVERIFY2(m_client->isReady(), qPrintable(m_client->error()));
        QVERIFY(m_client->logIn());
        QVERIFY(m_client->openDemoRoute());
        // The server's three vehicles first: addVciVehicles counts on the fleet it finds.
        QTRY_COMPARE_WITH_TIMEOUT(m_client->fleet().count(), 3, 10000);
        QVERIFY(m_client->addVciVehicles());
        // A vehicle chosen, so the fly view's instruments show numbers.
        m_client->showPage(2);
        auto *layer = m_client->find<ui::VehicleLayer>(QStringLiteral("vehicleLayer"));
        QVERIFY(layer);
        layer->setCurrentIndex(0);
        QTRY_VERIFY_WITH_TIMEOUT(textOf(*m_client, "value_altitudeAmsl").endsWith(QLatin1String(" m")), 10000);
    }

    void cleanupTestCase() { m_client.reset(); }
    // A check that failed half-way leaves English behind it, not German, for the next.
    void cleanup()
    {
        if (m_client)
            m_client->settings().setLanguage(QStringLiteral("en"));
    }

    // System, English and each compiled translation, named in its own language.
    void theSelectorListsTheLanguages()
    {
        const ui::Translations &translations = m_client->translations();
        QCOMPARE(translations.languageCodes(), (QStringList{QString(), QStringLiteral("en"), QStringLiteral("de")}));
        QCOMPARE(translations.languageNames().at(1), QStringLiteral("English"));
        QCOMPARE(translations.languageNames().at(2), QStringLiteral("Deutsch"));
        auto *box = m_client->find<QObject>(QStringLiteral("languageBox"));
        QVERIFY(box);
        QCOMPARE(box->property("count").toInt(), 3);
        QCOMPARE(box->property("currentIndex").toInt(), translations.chosenLanguage());
    }

    // Chosen in the selector: the tabs are German at once, the altitude has a decimal comma; back to
    // English, both come back. The choice is kept in the settings.
    void switchingRewordsAndReformatsAtOnce()
    {
        static const QRegularExpression englishAltitude(QStringLiteral("^-?\\d+\\.\\d m$"));
        static const QRegularExpression germanAltitude(QStringLiteral("^-?\\d+,\\d m$"));
        QCOMPARE(textOf(*m_client, "loginTab"), QStringLiteral("Login"));
        QCOMPARE(textOf(*m_client, "missionTab"), QStringLiteral("Mission"));
        QVERIFY2(englishAltitude.match(textOf(*m_client, "value_altitudeAmsl")).hasMatch(), qPrintable(textOf(*m_client, "value_altitudeAmsl")));

        auto *box = m_client->find<QObject>(QStringLiteral("languageBox"));
        QVERIFY(box);
        const int german = int(m_client->translations().languageCodes().indexOf(QStringLiteral("de")));
        box->setProperty("currentIndex", german);
        QMetaObject::invokeMethod(box, "activated", Q_ARG(int, german)); // as a click on "Deutsch" does
        QCOMPARE(m_client->settings().language(), QStringLiteral("de"));
        QCOMPARE(m_client->translations().active(), QStringLiteral("de"));
        QTRY_COMPARE(textOf(*m_client, "loginTab"), QStringLiteral("Anmeldung"));
        QCOMPARE(textOf(*m_client, "missionTab"), QStringLiteral("Einsatz"));
        QCOMPARE(textOf(*m_client, "telemetryTab"), QStringLiteral("Live-Telemetrie"));
        QTRY_VERIFY2(germanAltitude.match(textOf(*m_client, "value_altitudeAmsl")).hasMatch(), qPrintable(textOf(*m_client, "value_altitudeAmsl")));
        // The selector still shows the choice, in a list now made in German.
        QTRY_COMPARE(box->property("displayText").toString(), QStringLiteral("Deutsch"));
        QCOMPARE(m_client->translations().languageNames().at(0),
                 QStringLiteral("Sprache des Systems"));
        // Numbers anywhere DisplayUnits formats them, dates by the default locale.
        ui::DisplayUnits units;
        QCOMPARE(units.formatAltitude(12.5), QStringLiteral("12,5 m"));
        QCOMPARE(units.formatSpeed(3.26), QStringLiteral("3,3 m/s"));
        QCOMPARE(QLocale().decimalPoint(), QStringLiteral(","));

        m_client->settings().setLanguage(QStringLiteral("en"));
        QTRY_COMPARE(textOf(*m_client, "loginTab"), QStringLiteral("Login"));
        QTRY_VERIFY2(englishAltitude.match(textOf(*m_client, "value_altitudeAmsl")).hasMatch(), qPrintable(textOf(*m_client, "value_altitudeAmsl")));
        QCOMPARE(units.formatAltitude(12.5), QStringLiteral("12.5 m"));
        QTRY_COMPARE(box->property("displayText").toString(), QStringLiteral("English"));
    }

    // Words made by C++ (a model's role, a property, what a C++ item paints) follow a language change
    // without being made again by hand: the status line, the vehicle list's link state, the plot's
    // field names, the route's "Opened …" line, the map's attribution, the profile's headline, what
    // the route's analysis words (the endurance's missing profile).
    void cppWordsFollowTheLanguage()
    {
        m_client->showPage(1);
        const endurance::RouteEndurance &endurance = m_client->graph().endurance();
        const QString noProfile = QStringLiteral("No energy profile: choose the vehicle's profile file");
        QTRY_COMPARE(endurance.problem(), noProfile);
        auto *profile = m_client->find<QObject>(QStringLiteral("elevationProfile"));
        QVERIFY(profile);
        QTRY_VERIFY(!profile->property("headline").toString().isEmpty());
        const QString englishHeadline = profile->property("headline").toString();
        QVERIFY2(englishHeadline.startsWith(QLatin1String("lowest clearance")) || englishHeadline == QLatin1String("clearance unknown"),
                 qPrintable(englishHeadline));
        QVERIFY2(m_client->missions().message().startsWith(QLatin1String("Opened ")), qPrintable(m_client->missions().message()));
        const QString opened = m_client->missions().message();
        const QString version = opened.section(QLatin1String("(version "), 1).chopped(2);
        QTRY_VERIFY2(textOf(*m_client, "connectionStateLabel").startsWith(QStringLiteral("Ready — ")), qPrintable(textOf(*m_client, "connectionStateLabel")));
        QCOMPARE(textOf(*m_client, "attributionLabel"), QStringLiteral("Land outlines: Natural Earth"));
        m_client->showPage(2);
        QCOMPARE(m_client->find<QObject>(QStringLiteral("plotFieldPicker"))->property("displayText").toString(), QStringLiteral("Ground speed"));
        QTRY_VERIFY2(textsUnder(m_client->find<QObject>(QStringLiteral("vehicleList"))).filter(QRegularExpression(QStringLiteral("·\\s+connected$"))).size() >= 3,
                     qPrintable(textsUnder(m_client->find<QObject>(QStringLiteral("vehicleList"))).join(QLatin1String(" | "))));

        m_client->settings().setLanguage(QStringLiteral("de"));
        QTRY_COMPARE(textOf(*m_client, "loginTab"), QStringLiteral("Anmeldung"));
        QTRY_VERIFY2(textOf(*m_client, "connectionStateLabel").startsWith(QStringLiteral("Bereit — ")), qPrintable(textOf(*m_client, "connectionStateLabel")));
        QVERIFY2(textOf(*m_client, "connectionStateLabel").contains(QLatin1String(" auf ")), qPrintable(textOf(*m_client, "connectionStateLabel")));
        QTRY_COMPARE(m_client->find<QObject>(QStringLiteral("plotFieldPicker"))->property("displayText").toString(),
                     QStringLiteral("Geschwindigkeit über Grund"));
        // The picker shows the name and adds the key: the plot and its chip get "groundSpeed", worded.
        QMetaObject::invokeMethod(m_client->find<QObject>(QStringLiteral("plotAddButton")), "clicked");
        QTRY_VERIFY(m_client->find<QObject>(QStringLiteral("telemetryPlot"))->property("fields").toStringList().contains(QStringLiteral("groundSpeed")));
        QTRY_VERIFY2(textsUnder(m_client->find<QObject>(QStringLiteral("plotFieldChips"))).contains(QStringLiteral("Geschwindigkeit über Grund  ×")),
                     qPrintable(textsUnder(m_client->find<QObject>(QStringLiteral("plotFieldChips"))).join(QLatin1String(" | "))));
        QTRY_VERIFY2(textsUnder(m_client->find<QObject>(QStringLiteral("vehicleList"))).filter(QRegularExpression(QStringLiteral("·\\s+verbunden$"))).size() >= 3,
                     qPrintable(textsUnder(m_client->find<QObject>(QStringLiteral("vehicleList"))).join(QLatin1String(" | "))));
        QCOMPARE(m_client->missions().message(), QStringLiteral("%1 geöffnet (Version %2).").arg(m_client->missions().routeName(), version));
        QTRY_COMPARE(textOf(*m_client, "attributionLabel"), QStringLiteral("Landumrisse: Natural Earth"));
        const QString germanHeadline = profile->property("headline").toString();
        QTRY_COMPARE(endurance.problem(), QStringLiteral("Kein Energieprofil: Wählen Sie die Profildatei des Fahrzeugs"));
        QVERIFY2(germanHeadline.startsWith(QLatin1String("geringster Abstand")) || germanHeadline == QLatin1String("Abstand unbekannt"),
                 qPrintable(germanHeadline));
        // Its number in German's format, as every number the views show (the server's terrain
        // answers in the demo, so the clearance is known).
        if (englishHeadline.startsWith(QLatin1String("lowest clearance")))
            QVERIFY2(germanHeadline.contains(QRegularExpression(QStringLiteral("^geringster Abstand -?\\d+,\\d m$"))), qPrintable(germanHeadline));

        m_client->settings().setLanguage(QStringLiteral("en"));
        QTRY_VERIFY2(textOf(*m_client, "connectionStateLabel").startsWith(QStringLiteral("Ready — ")), qPrintable(textOf(*m_client, "connectionStateLabel")));
        QCOMPARE(m_client->missions().message(), opened);
        QCOMPARE(profile->property("headline").toString(), englishHeadline);
        QTRY_COMPARE(endurance.problem(), noProfile);
        QTRY_COMPARE(textOf(*m_client, "attributionLabel"), QStringLiteral("Land outlines: Natural Earth"));
        QTRY_COMPARE(m_client->find<QObject>(QStringLiteral("plotFieldPicker"))->property("displayText").toString(), QStringLiteral("Ground speed"));
    }

    // A number field takes what a German operator types ("2,5"), refuses what is out of its range
    // with the reason in German, and shows its number again in English after a change.
    void numbersAreTypedAsTheLanguageWritesThem()
    {
        m_client->showPage(1);
        endurance::RouteEndurance &endurance = m_client->graph().endurance();
        endurance.setWindSpeed(0);
        m_client->settings().setLanguage(QStringLiteral("de"));
        QTRY_COMPARE(textOf(*m_client, "loginTab"), QStringLiteral("Anmeldung"));
        auto *field = m_client->find<QQuickItem>(QStringLiteral("windSpeedField"));
        QVERIFY(field);
        QTRY_VERIFY(field->isVisible());
        QCOMPARE(field->property("text").toString(), QStringLiteral("0"));
        const auto type = [&](const QString &text) {
            field->forceActiveFocus();
            QMetaObject::invokeMethod(field, "selectAll");
            for (const QChar c : text)
                QTest::keyClick(m_client->window(), c.toLatin1());
            QTest::keyClick(m_client->window(), Qt::Key_Return);
        };
        type(QStringLiteral("2,5"));
        QCOMPARE(endurance.windSpeed(), 2.5);
        QTRY_COMPARE(field->property("text").toString(), QStringLiteral("2,5"));
        type(QStringLiteral("70"));  // beyond the field's 60 m/s
        QCOMPARE(endurance.windSpeed(), 2.5);
        QVERIFY(field->property("refused").toBool());
        QCOMPARE(field->property("reason").toString(), QStringLiteral("Von 0 bis 60"));
        type(QStringLiteral("3,25"));
        QCOMPARE(endurance.windSpeed(), 3.25);
        QVERIFY(!field->property("refused").toBool());
        m_client->settings().setLanguage(QStringLiteral("en"));
        QTRY_COMPARE(field->property("text").toString(), QStringLiteral("3.25"));
        endurance.setWindSpeed(0);
    }

    // Qt's own words come from Qt's translations (Debian's qt6-translations-l10n): in German, a
    // dialog's Cancel button reads "Abbrechen". Without the package this fails, saying so.
    void qtsOwnWordsFollowTheLanguage()
    {
        const QString qtbase = QLibraryInfo::path(QLibraryInfo::TranslationsPath) + QStringLiteral("/qtbase_de.qm");
        if (!QFile::exists(qtbase))
            QFAIL(qPrintable(QStringLiteral("%1 is missing: install qt6-translations-l10n (scripts/install-deps.sh)").arg(qtbase)));
        QObject *dialog = m_client->find<QObject>(QStringLiteral("mapSourceDialog"));
        QVERIFY(dialog);
        QCOMPARE(standardButtonText(dialog, "Cancel"), QStringLiteral("Cancel"));
        m_client->settings().setLanguage(QStringLiteral("de"));
        QTRY_COMPARE(standardButtonText(dialog, "Cancel"), QStringLiteral("Abbrechen"));
        m_client->settings().setLanguage(QStringLiteral("en"));
        QTRY_COMPARE(standardButtonText(dialog, "Cancel"), QStringLiteral("Cancel"));
    }

    // The real German, compiled into the program, once it has landed: the tabs read what its
    // translator says, not English.
    void theProgramsGerman()
    {
        QTranslator german;
        if (!german.load(QStringLiteral(":/i18n/sortie_de.qm")))
            QFAIL("no German compiled into the program (:/i18n/sortie_de.qm): resources/i18n/sortie_de.ts is missing or was not built");
        const QString login = german.translate("Main", "Login");
        QVERIFY2(!login.isEmpty() && login != QLatin1String("Login"), qPrintable(login));
        test::ClientWindow client; // the program's own translations
        QVERIFY2(client.isReady(), qPrintable(client.error()));
        QVERIFY(client.translations().languageCodes().contains(QStringLiteral("de")));
        client.settings().setLanguage(QStringLiteral("de"));
        QTRY_COMPARE(textOf(client, "loginTab"), login);
        QCOMPARE(ui::DisplayUnits().formatAltitude(12.5), QStringLiteral("12,5 m"));
        client.settings().setLanguage(QStringLiteral("en"));
        QTRY_COMPARE(textOf(client, "loginTab"), QStringLiteral("Login"));
        // English has its plurals (resources/i18n/sortie_en.ts): "1 corner", "5 corners", never "corner(s)".
        const char *context = "sortie::maptiles::OfflineMaps";
        QCOMPARE(QCoreApplication::translate(context, "A drawn area (%n corner(s))", nullptr, 5), QStringLiteral("A drawn area (5 corners)"));
        QCOMPARE(QCoreApplication::translate("sortie::mission::RouteEditor", "Move %n segment(s)", nullptr, 1), QStringLiteral("Move 1 segment"));
        QCOMPARE(client.translations().languageCodes().count(QStringLiteral("en")), 1);
        // In German the German forms, not the English ones.
        client.settings().setLanguage(QStringLiteral("de"));
        QTRY_COMPARE(textOf(client, "loginTab"), login);
        QCOMPARE(QCoreApplication::translate(context, "A drawn area (%n corner(s))", nullptr, 5), QStringLiteral("Ein gezeichnetes Gebiet (5 Ecken)"));
        client.settings().setLanguage(QStringLiteral("en"));
        QTRY_COMPARE(textOf(client, "loginTab"), QStringLiteral("Login"));
    }
};

QTEST_MAIN(TestTranslations)
#include "tst_translations.moc"
