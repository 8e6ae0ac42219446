#pragma once

#include "ThemeColours.h"

#include <QObject>
#include <QStringList>

namespace sortie::ui {

// The client's look in one object: every colour the views and the painted layers use, the
// spacing, the controls' height (touch-sized) and the type sizes. It has four schemes: System
// follows the platform's palette (and its changes), Light and Dark are Sortie's own, Sunlight is a
// high-contrast dark one for a screen in the sun (every pair of words and ground at 7:1 or more).
// ui::MainWindow makes the program's one and hands it to Main.qml as a required property, and
// Main.qml to the pages; it follows AppSettings::colourScheme. A view's colour is a binding to one
// of these properties, never a literal (tests/ui/check_colour_literals.py).
class Theme : public QObject
{
    Q_OBJECT
    Q_PROPERTY(Scheme scheme READ scheme WRITE setScheme NOTIFY schemeChanged)
    // The schemes for a selector, in one order: their settings' codes ("system", "light", …), their
    // names in the operator's language, and the index of the scheme in use.
    Q_PROPERTY(QStringList schemeCodes READ schemeCodes CONSTANT)
    Q_PROPERTY(QStringList schemeNames READ schemeNames NOTIFY schemesChanged)
    Q_PROPERTY(int schemeIndex READ schemeIndex NOTIFY schemeChanged)
    // True when the window's ground is dark (Dark, Sunlight, a dark platform palette).
    Q_PROPERTY(bool darkGround READ darkGround NOTIFY coloursChanged)
    Q_PROPERTY(QColor window READ window NOTIFY coloursChanged)
    Q_PROPERTY(QColor windowText READ windowText NOTIFY coloursChanged)
    Q_PROPERTY(QColor base READ base NOTIFY coloursChanged)
    Q_PROPERTY(QColor alternateBase READ alternateBase NOTIFY coloursChanged)
    Q_PROPERTY(QColor text READ text NOTIFY coloursChanged)
    Q_PROPERTY(QColor button READ button NOTIFY coloursChanged)
    Q_PROPERTY(QColor buttonText READ buttonText NOTIFY coloursChanged)
    Q_PROPERTY(QColor highlight READ highlight NOTIFY coloursChanged)
    Q_PROPERTY(QColor highlightedText READ highlightedText NOTIFY coloursChanged)
    Q_PROPERTY(QColor placeholderText READ placeholderText NOTIFY coloursChanged)
    Q_PROPERTY(QColor toolTipBase READ toolTipBase NOTIFY coloursChanged)
    Q_PROPERTY(QColor toolTipText READ toolTipText NOTIFY coloursChanged)
    Q_PROPERTY(QColor link READ link NOTIFY coloursChanged)
    Q_PROPERTY(QColor light READ light NOTIFY coloursChanged)
    Q_PROPERTY(QColor midlight READ midlight NOTIFY coloursChanged)
    Q_PROPERTY(QColor mid READ mid NOTIFY coloursChanged)
    Q_PROPERTY(QColor dark READ dark NOTIFY coloursChanged)
    Q_PROPERTY(QColor shadow READ shadow NOTIFY coloursChanged)
    Q_PROPERTY(QColor problem READ problem NOTIFY coloursChanged)
    Q_PROPERTY(QColor warning READ warning NOTIFY coloursChanged)
    Q_PROPERTY(QColor ok READ ok NOTIFY coloursChanged)
    Q_PROPERTY(QColor info READ info NOTIFY coloursChanged)
    Q_PROPERTY(QColor missing READ missing NOTIFY coloursChanged)
    Q_PROPERTY(QColor problemText READ problemText NOTIFY coloursChanged)
    Q_PROPERTY(QColor warningText READ warningText NOTIFY coloursChanged)
    Q_PROPERTY(QColor okText READ okText NOTIFY coloursChanged)
    Q_PROPERTY(QColor infoText READ infoText NOTIFY coloursChanged)
    Q_PROPERTY(QColor missingText READ missingText NOTIFY coloursChanged)
    Q_PROPERTY(QColor onProblem READ onProblem NOTIFY coloursChanged)
    Q_PROPERTY(QColor onWarning READ onWarning NOTIFY coloursChanged)
    Q_PROPERTY(QColor onReplay READ onReplay NOTIFY coloursChanged)
    Q_PROPERTY(QColor noticeBackground READ noticeBackground NOTIFY coloursChanged)
    Q_PROPERTY(QColor noticeText READ noticeText NOTIFY coloursChanged)
    Q_PROPERTY(QColor noticeBorder READ noticeBorder NOTIFY coloursChanged)
    Q_PROPERTY(QColor overlay READ overlay NOTIFY coloursChanged)
    Q_PROPERTY(QColor overlayText READ overlayText NOTIFY coloursChanged)
    Q_PROPERTY(QColor accent READ accent NOTIFY coloursChanged)
    Q_PROPERTY(QColor replay READ replay NOTIFY coloursChanged)
    Q_PROPERTY(QColor rowSelected READ rowSelected NOTIFY coloursChanged)
    Q_PROPERTY(QColor rowStripe READ rowStripe NOTIFY coloursChanged)
    // The map's marks, for the layers a view colours (MapPalette: route, draft, ghost, zones).
    Q_PROPERTY(QColor mapRoute READ mapRoute NOTIFY coloursChanged)
    Q_PROPERTY(QColor mapSky READ mapSky NOTIFY coloursChanged)         // the 3D view's background
    Q_PROPERTY(QColor mapAmbient READ mapAmbient NOTIFY coloursChanged) // the 3D view's ambient light
    Q_PROPERTY(QColor mapDraft READ mapDraft NOTIFY coloursChanged)
    Q_PROPERTY(QColor mapGhost READ mapGhost NOTIFY coloursChanged)
    Q_PROPERTY(QColor mapExclusion READ mapExclusion NOTIFY coloursChanged)
    Q_PROPERTY(QColor mapAuthorisation READ mapAuthorisation NOTIFY coloursChanged)
    Q_PROPERTY(QColor mapConditional READ mapConditional NOTIFY coloursChanged)
    Q_PROPERTY(QColor mapInformation READ mapInformation NOTIFY coloursChanged)
    Q_PROPERTY(QColor mapInclusion READ mapInclusion NOTIFY coloursChanged)
    // Spacing between controls and around groups; the height of a control a finger can hit; the
    // icons' size; type sizes in pixels (body text, small print, titles, the glance bar's values).
    Q_PROPERTY(int spacing READ spacing CONSTANT)
    Q_PROPERTY(int smallSpacing READ smallSpacing CONSTANT)
    Q_PROPERTY(int controlHeight READ controlHeight CONSTANT)
    Q_PROPERTY(int iconSize READ iconSize CONSTANT)
    Q_PROPERTY(int fontSize READ fontSize NOTIFY fontsChanged)
    Q_PROPERTY(int smallFontSize READ smallFontSize NOTIFY fontsChanged)
    Q_PROPERTY(int titleFontSize READ titleFontSize NOTIFY fontsChanged)

public:
    enum class Scheme { System, Light, Dark, Sunlight };
    Q_ENUM(Scheme)

    static constexpr int kControlHeight = 40; // px: a finger's width (touch-sized, WCAG 2.5.5's 44 pt at 1.1 px/pt)

    explicit Theme(QObject *parent = nullptr);
    ~Theme() override;

    Scheme scheme() const { return m_scheme; }
    void setScheme(Scheme scheme);
    // The names AppSettings keeps ("system", "light", "dark", "sunlight"); anything else is System.
    static Scheme schemeFromName(const QString &name);
    static QString nameOf(Scheme scheme);
    // The scheme's colours, for C++: the map and its layers, the instruments, the tests.
    const ThemeColours &colours() const { return m_colours; }
    const MapPalette &mapPalette() const { return m_colours.map; }
    // The colours of `scheme` (System: the platform palette given).
    static ThemeColours coloursOf(Scheme scheme, const QPalette &platform);
    QStringList schemeCodes() const;
    QStringList schemeNames() const;
    int schemeIndex() const;
    bool darkGround() const { return m_colours.isDark(); }

    QColor window() const { return m_colours.window; }
    QColor windowText() const { return m_colours.windowText; }
    QColor base() const { return m_colours.base; }
    QColor alternateBase() const { return m_colours.alternateBase; }
    QColor text() const { return m_colours.text; }
    QColor button() const { return m_colours.button; }
    QColor buttonText() const { return m_colours.buttonText; }
    QColor highlight() const { return m_colours.highlight; }
    QColor highlightedText() const { return m_colours.highlightedText; }
    QColor placeholderText() const { return m_colours.placeholderText; }
    QColor toolTipBase() const { return m_colours.toolTipBase; }
    QColor toolTipText() const { return m_colours.toolTipText; }
    QColor link() const { return m_colours.link; }
    QColor light() const { return m_colours.light; }
    QColor midlight() const { return m_colours.midlight; }
    QColor mid() const { return m_colours.mid; }
    QColor dark() const { return m_colours.dark; }
    QColor shadow() const { return m_colours.shadow; }
    QColor problem() const { return m_colours.problem; }
    QColor warning() const { return m_colours.warning; }
    QColor ok() const { return m_colours.ok; }
    QColor info() const { return m_colours.info; }
    QColor missing() const { return m_colours.missing; }
    QColor problemText() const { return m_colours.problemText; }
    QColor warningText() const { return m_colours.warningText; }
    QColor okText() const { return m_colours.okText; }
    QColor infoText() const { return m_colours.infoText; }
    QColor missingText() const { return m_colours.missingText; }
    QColor onProblem() const { return m_colours.onProblem; }
    QColor onWarning() const { return m_colours.onWarning; }
    QColor onReplay() const { return m_colours.onReplay; }
    QColor noticeBackground() const { return m_colours.noticeBackground; }
    QColor noticeText() const { return m_colours.noticeText; }
    QColor noticeBorder() const { return m_colours.noticeBorder; }
    QColor overlay() const { return m_colours.overlay; }
    QColor overlayText() const { return m_colours.overlayText; }
    QColor accent() const { return m_colours.accent; }
    QColor replay() const { return m_colours.replay; }
    QColor rowSelected() const { return m_colours.rowSelected; }
    QColor rowStripe() const { return m_colours.rowStripe; }
    QColor mapRoute() const { return m_colours.map.route; }
    QColor mapSky() const { return m_colours.map.sceneSky; }
    QColor mapAmbient() const { return m_colours.map.sceneAmbient; }
    QColor mapDraft() const { return m_colours.map.draft; }
    QColor mapGhost() const { return m_colours.map.ghost; }
    QColor mapExclusion() const { return m_colours.map.exclusion; }
    QColor mapInclusion() const { return m_colours.map.inclusion; }
    QColor mapAuthorisation() const { return m_colours.map.authorisation; }
    QColor mapConditional() const { return m_colours.map.conditional; }
    QColor mapInformation() const { return m_colours.map.information; }

    int spacing() const { return 8; }
    int smallSpacing() const { return 4; }
    int controlHeight() const { return kControlHeight; }
    int iconSize() const { return 24; }
    int fontSize() const;
    int smallFontSize() const;
    int titleFontSize() const;

signals:
    void schemeChanged();
    // All colours change together, with the scheme or the platform's palette.
    void coloursChanged();
    void schemesChanged();
    void fontsChanged();

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void update();

    Scheme m_scheme = Scheme::System;
    ThemeColours m_colours;
};

// The colours of `theme`, or the light scheme's for an item not handed one (a view on its own).
const ThemeColours &coloursOf(const Theme *theme);

} // namespace sortie::ui
