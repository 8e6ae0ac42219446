// The theme (ui/theme): WCAG contrast arithmetic against known values, every scheme's pairs of
// words and ground at 4.5:1 (7:1 in sunlight), System following the platform's palette, and the
// scheme's names as AppSettings keeps them.
#include "Contrast.h"
#include "Theme.h"
#include "ThemeColours.h"

#include <QGuiApplication>
#include <QSignalSpy>
#include <QTest>

using namespace sortie::ui;

namespace {

struct Pair
{
    const char *name;
    QColor words;
    QColor ground;
};

// Every pair of words and the ground they are read on, as the views use them.
std::vector<Pair> readingPairs(const ThemeColours &c)
{
    std::vector<Pair> pairs = {
        {"windowText on window", c.windowText, c.window},
        {"text on base", c.text, c.base},
        {"text on alternateBase", c.text, c.alternateBase},
        {"buttonText on button", c.buttonText, c.button},
        {"highlightedText on highlight", c.highlightedText, c.highlight},
        {"toolTipText on toolTipBase", c.toolTipText, c.toolTipBase},
        {"placeholderText on base", c.placeholderText, c.base},
        {"link on base", c.link, c.base},
        {"noticeText on noticeBackground", c.noticeText, c.noticeBackground},
        {"onProblem on problem", c.onProblem, c.problem},
        {"onWarning on warning", c.onWarning, c.warning},
        {"text on a chosen row", c.text, contrast::over(c.rowSelected, c.base)},
        {"overlayText on overlay over land", c.overlayText, contrast::over(c.overlay, c.map.land)},
        {"overlayText on overlay over sea", c.overlayText, contrast::over(c.overlay, c.map.sea)},
    };
    for (const auto &[name, colour] : {std::pair{"problemText", c.problemText}, {"warningText", c.warningText},
                                       {"okText", c.okText}, {"infoText", c.infoText}, {"missingText", c.missingText}}) {
        pairs.push_back({name, colour, c.window});
        pairs.push_back({name, colour, c.base});
    }
    return pairs;
}

// The platform's dark palette a desktop might hand (the tests' dark one).
QPalette darkPlatform()
{
    QPalette dark;
    dark.setColor(QPalette::Window, QColor(0x2b, 0x2b, 0x2b));
    dark.setColor(QPalette::WindowText, QColor(0xe0, 0xe0, 0xe0));
    dark.setColor(QPalette::Base, QColor(0x1e, 0x1e, 0x1e));
    dark.setColor(QPalette::Text, QColor(0xe0, 0xe0, 0xe0));
    return dark;
}

} // namespace

class TestTheme : public QObject
{
    Q_OBJECT

private slots:
    void luminanceAndRatioAreWcags()
    {
        QCOMPARE(contrast::relativeLuminance(Qt::black), 0.0);
        QCOMPARE(contrast::relativeLuminance(Qt::white), 1.0);
        QCOMPARE(contrast::ratio(Qt::black, Qt::white), 21.0);
        QCOMPARE(contrast::ratio(Qt::white, Qt::black), 21.0); // either order
        QCOMPARE(contrast::ratio(QColor(0x77, 0x77, 0x77), QColor(0x77, 0x77, 0x77)), 1.0);
        // Known figures (WebAIM's checker): #777 on white 4.48, #767676 on white 4.54, #0000ff on white 8.59.
        QVERIFY(std::abs(contrast::ratio(QColor(0x77, 0x77, 0x77), Qt::white) - 4.48) < 0.01);
        QVERIFY(std::abs(contrast::ratio(QColor(0x76, 0x76, 0x76), Qt::white) - 4.54) < 0.01);
        QVERIFY(std::abs(contrast::ratio(QColor(0x00, 0x00, 0xff), Qt::white) - 8.59) < 0.01);
        // A translucent black over white is grey.
        const QColor grey = contrast::over(QColor(0, 0, 0, 128), Qt::white);
        QVERIFY(std::abs(grey.redF() - 0.498) < 0.01 && grey.red() == grey.blue());
    }

    void everySchemeReadsWell_data()
    {
        QTest::addColumn<int>("scheme");
        QTest::addColumn<double>("minimum");
        QTest::newRow("light") << int(Theme::Scheme::Light) << 4.5;
        QTest::newRow("dark") << int(Theme::Scheme::Dark) << 4.5;
        QTest::newRow("sunlight") << int(Theme::Scheme::Sunlight) << 7.0;
    }

    void everySchemeReadsWell()
    {
        QFETCH(int, scheme);
        QFETCH(double, minimum);
        const ThemeColours colours = Theme::coloursOf(Theme::Scheme(scheme), QPalette());
        QStringList weak;
        for (const Pair &pair : readingPairs(colours)) {
            const double ratio = contrast::ratio(pair.words, pair.ground);
            if (ratio < minimum)
                weak << QStringLiteral("%1: %2 on %3 is %4:1").arg(QLatin1String(pair.name), pair.words.name(), pair.ground.name()).arg(ratio, 0, 'f', 2);
        }
        QVERIFY2(weak.isEmpty(), qPrintable(weak.join(QStringLiteral("; "))));
    }

    void theSystemsStatesReadWellOnItsPalette_data()
    {
        QTest::addColumn<QPalette>("platform");
        QTest::newRow("Qt's default (light)") << QPalette();
        QTest::newRow("a dark desktop") << darkPlatform();
    }

    // The platform's own roles are the platform's; the states Sortie adds must read on them.
    void theSystemsStatesReadWellOnItsPalette()
    {
        QFETCH(QPalette, platform);
        const ThemeColours c = ThemeColours::fromPlatform(platform);
        QCOMPARE(c.window, platform.color(QPalette::Window));
        QCOMPARE(c.text, platform.color(QPalette::Text));
        for (const QColor &state : {c.problemText, c.warningText, c.okText, c.infoText}) {
            QVERIFY2(contrast::ratio(state, c.window) >= 4.5, qPrintable(state.name() + QStringLiteral(" on ") + c.window.name()));
            QVERIFY2(contrast::ratio(state, c.base) >= 4.5, qPrintable(state.name() + QStringLiteral(" on ") + c.base.name()));
        }
    }

    void schemesDiffer()
    {
        const ThemeColours light = ThemeColours::lightScheme(), dark = ThemeColours::darkScheme(), sun = ThemeColours::sunlightScheme();
        QVERIFY(!light.isDark());
        QVERIFY(dark.isDark());
        QVERIFY(sun.isDark());
        QVERIFY(contrast::relativeLuminance(light.window) > 0.8);
        QVERIFY(contrast::relativeLuminance(dark.window) < 0.05);
        QCOMPARE(sun.window, QColor(Qt::black));
        QVERIFY(contrast::ratio(sun.windowText, sun.window) > contrast::ratio(dark.windowText, dark.window));
        QCOMPARE(light.map, MapPalette::light());
        QCOMPARE(dark.map, MapPalette::dark());
        QCOMPARE(sun.map, MapPalette::sunlight());
        // The map's words read on its land in every scheme.
        for (const MapPalette &map : {MapPalette::light(), MapPalette::dark(), MapPalette::sunlight()})
            QVERIFY2(contrast::ratio(map.label, map.land) >= 4.5, qPrintable(map.label.name() + QStringLiteral(" on ") + map.land.name()));
    }

    void namesAsTheSettingsKeepThem()
    {
        for (Theme::Scheme s : {Theme::Scheme::System, Theme::Scheme::Light, Theme::Scheme::Dark, Theme::Scheme::Sunlight})
            QCOMPARE(Theme::schemeFromName(Theme::nameOf(s)), s);
        QCOMPARE(Theme::nameOf(Theme::Scheme::Sunlight), QStringLiteral("sunlight"));
        QCOMPARE(Theme::schemeFromName(QStringLiteral("no such scheme")), Theme::Scheme::System);
        QCOMPARE(Theme::schemeFromName(QString()), Theme::Scheme::System);
        Theme theme;
        QCOMPARE(theme.schemeCodes(), (QStringList{"system", "light", "dark", "sunlight"}));
        QCOMPARE(theme.schemeNames().size(), 4);
        QVERIFY(!theme.schemeNames().at(3).isEmpty());
        QCOMPARE(theme.schemeIndex(), 0);
        theme.setScheme(Theme::Scheme::Sunlight);
        QCOMPARE(theme.schemeIndex(), 3);
    }

    void changesItsColoursWithTheScheme()
    {
        Theme theme;
        QCOMPARE(theme.scheme(), Theme::Scheme::System);
        QSignalSpy colours(&theme, &Theme::coloursChanged);
        QSignalSpy scheme(&theme, &Theme::schemeChanged);
        theme.setScheme(Theme::Scheme::Sunlight);
        QCOMPARE(scheme.count(), 1);
        QCOMPARE(colours.count(), 1);
        QCOMPARE(theme.window(), QColor(Qt::black));
        QVERIFY(theme.darkGround());
        QCOMPARE(theme.mapPalette(), MapPalette::sunlight());
        theme.setScheme(Theme::Scheme::Sunlight); // no change, no signal
        QCOMPARE(colours.count(), 1);
        theme.setScheme(Theme::Scheme::Light);
        QCOMPARE(theme.window(), ThemeColours::lightScheme().window);
        QVERIFY(!theme.darkGround());
        QVERIFY(theme.controlHeight() >= 40); // touch-sized
        QVERIFY(theme.fontSize() >= 14);
    }

    void systemFollowsThePlatformsPalette()
    {
        Theme theme;
        QSignalSpy colours(&theme, &Theme::coloursChanged);
        QGuiApplication::setPalette(darkPlatform());
        QTRY_COMPARE(colours.count(), 1);
        QCOMPARE(theme.window(), QColor(0x2b, 0x2b, 0x2b));
        QVERIFY(theme.darkGround());
        QCOMPARE(theme.problemText(), ThemeColours::darkScheme().problemText); // the dark states on a dark desktop
        // A scheme of its own does not follow the platform.
        theme.setScheme(Theme::Scheme::Light);
        const int before = int(colours.count());
        QGuiApplication::setPalette(QPalette());
        QCoreApplication::processEvents();
        QCOMPARE(int(colours.count()), before);
        QCOMPARE(theme.window(), ThemeColours::lightScheme().window);
    }
};

QTEST_MAIN(TestTheme)
#include "tst_theme.moc"
