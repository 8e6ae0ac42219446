#include "ThemeColours.h"

#include "Contrast.h"

namespace sortie::ui {

namespace {
QColor rgb(QRgb value)
{
    return QColor::fromRgb(value);
}
QColor rgba(int r, int g, int b, int alpha)
{
    return QColor(r, g, b, alpha);
}

// The states, notice, overlays and rows for a light ground.
void lightStates(ThemeColours &c)
{
    c.problem = rgb(0xc62828);
    c.warning = rgb(0xfb8c00);
    c.ok = rgb(0x43a047);
    c.info = rgb(0x1e88e5);
    c.missing = rgb(0x9e9e9e);
    c.problemText = rgb(0xb71c1c);
    c.warningText = rgb(0x8a4b00);
    c.okText = rgb(0x1b5e20);
    c.infoText = rgb(0x0d47a1);
    c.missingText = rgb(0x5f6368);
    c.onProblem = rgb(0xffffff);
    c.onWarning = rgb(0x000000);
    c.noticeBackground = rgb(0xfff3e0);
    c.noticeText = rgb(0x5d4037);
    c.noticeBorder = rgb(0xfb8c00);
    c.overlay = rgba(255, 255, 255, 205);
    c.overlayText = rgb(0x1a1a1a);
    c.accent = rgb(0x1e88e5);
    c.replay = rgb(0x8e24aa);
    c.onReplay = rgb(0xffffff);
    c.rowSelected = rgba(255, 143, 0, 64);
    c.rowStripe = rgba(128, 128, 128, 20);
}

// The same for a dark ground.
void darkStates(ThemeColours &c)
{
    c.problem = rgb(0xc62828);
    c.warning = rgb(0xfb8c00);
    c.ok = rgb(0x43a047);
    c.info = rgb(0x1e88e5);
    c.missing = rgb(0x757575);
    c.problemText = rgb(0xff8a80);
    c.warningText = rgb(0xffb74d);
    c.okText = rgb(0x81c784);
    c.infoText = rgb(0x8ab4f8);
    c.missingText = rgb(0x9aa0a6);
    c.onProblem = rgb(0xffffff);
    c.onWarning = rgb(0x000000);
    c.noticeBackground = rgb(0x3e2c14);
    c.noticeText = rgb(0xffe0b2);
    c.noticeBorder = rgb(0xfb8c00);
    c.overlay = rgba(0, 0, 0, 150);
    c.overlayText = rgb(0xffffff);
    c.accent = rgb(0x64b5f6);
    c.replay = rgb(0xce93d8);
    c.onReplay = rgb(0x000000);
    c.rowSelected = rgba(255, 143, 0, 77);
    c.rowStripe = rgba(255, 255, 255, 13);
}
} // namespace

ThemeColours ThemeColours::lightScheme()
{
    ThemeColours c;
    c.window = rgb(0xf3f4f6);
    c.windowText = rgb(0x1a1a1a);
    c.base = rgb(0xffffff);
    c.alternateBase = rgb(0xf0f1f3);
    c.text = rgb(0x1a1a1a);
    c.button = rgb(0xe8e9ec);
    c.buttonText = rgb(0x1a1a1a);
    c.highlight = rgb(0x1565c0);
    c.highlightedText = rgb(0xffffff);
    c.placeholderText = rgb(0x5f6368);
    c.toolTipBase = rgb(0xffffdc);
    c.toolTipText = rgb(0x1a1a1a);
    c.link = rgb(0x0b57d0);
    c.light = rgb(0xffffff);
    c.midlight = rgb(0xf0f0f0);
    c.mid = rgb(0xa0a0a0);
    c.dark = rgb(0x7a7a7a);
    c.shadow = rgb(0x3c3c3c);
    lightStates(c);
    c.map = MapPalette::light();
    return c;
}

ThemeColours ThemeColours::darkScheme()
{
    ThemeColours c;
    c.window = rgb(0x202124);
    c.windowText = rgb(0xe8eaed);
    c.base = rgb(0x17181a);
    c.alternateBase = rgb(0x26282b);
    c.text = rgb(0xe8eaed);
    c.button = rgb(0x303134);
    c.buttonText = rgb(0xe8eaed);
    c.highlight = rgb(0x8ab4f8);
    c.highlightedText = rgb(0x0b1a33);
    c.placeholderText = rgb(0x9aa0a6);
    c.toolTipBase = rgb(0x3c4043);
    c.toolTipText = rgb(0xe8eaed);
    c.link = rgb(0x8ab4f8);
    c.light = rgb(0x4a4d51);
    c.midlight = rgb(0x3c4043);
    c.mid = rgb(0x5f6368);
    c.dark = rgb(0x111214);
    c.shadow = rgb(0x000000);
    darkStates(c);
    c.map = MapPalette::dark();
    return c;
}

ThemeColours ThemeColours::sunlightScheme()
{
    ThemeColours c;
    c.window = rgb(0x000000);
    c.windowText = rgb(0xffffff);
    // Fields and buttons a step above the black ground: the style draws their edges from the
    // window's colour (darker still), so their own fill is what shows where they are.
    c.base = rgb(0x1c1c1c);
    c.alternateBase = rgb(0x2a2a2a);
    c.text = rgb(0xffffff);
    c.button = rgb(0x2e2e2e);
    c.buttonText = rgb(0xffffff);
    c.highlight = rgb(0xffd600);
    c.highlightedText = rgb(0x000000);
    c.placeholderText = rgb(0xc8c8c8);
    c.toolTipBase = rgb(0x000000);
    c.toolTipText = rgb(0xffffff);
    c.link = rgb(0x80d8ff);
    // Frames drawn light on black, so every field and button has a visible edge.
    c.light = rgb(0x5a5a5a);
    c.midlight = rgb(0x3a3a3a);
    c.mid = rgb(0xbdbdbd);
    c.dark = rgb(0x9e9e9e);
    c.shadow = rgb(0x000000);
    // Bright fills with black words: in the sun, light on dark reads best.
    c.problem = rgb(0xff8a8a);
    c.warning = rgb(0xffd600);
    c.ok = rgb(0x69f0ae);
    c.info = rgb(0x80d8ff);
    c.missing = rgb(0xbdbdbd);
    c.problemText = rgb(0xff8a8a);
    c.warningText = rgb(0xffd600);
    c.okText = rgb(0x69f0ae);
    c.infoText = rgb(0x80d8ff);
    c.missingText = rgb(0xbdbdbd);
    c.onProblem = rgb(0x000000);
    c.onWarning = rgb(0x000000);
    c.noticeBackground = rgb(0x000000);
    c.noticeText = rgb(0xffd600);
    c.noticeBorder = rgb(0xffd600);
    c.overlay = rgba(0, 0, 0, 220);
    c.overlayText = rgb(0xffffff);
    c.accent = rgb(0x80d8ff);
    c.replay = rgb(0xea80fc);
    c.onReplay = rgb(0x000000);
    c.rowSelected = rgba(255, 214, 0, 70);
    c.rowStripe = rgba(255, 255, 255, 20);
    c.map = MapPalette::sunlight();
    return c;
}

ThemeColours ThemeColours::fromPlatform(const QPalette &platform)
{
    const bool darkGround = platform.color(QPalette::Window).lightnessF() < 0.5;
    ThemeColours c = darkGround ? darkScheme() : lightScheme();
    c.window = platform.color(QPalette::Window);
    c.windowText = platform.color(QPalette::WindowText);
    c.base = platform.color(QPalette::Base);
    c.alternateBase = platform.color(QPalette::AlternateBase);
    c.text = platform.color(QPalette::Text);
    c.button = platform.color(QPalette::Button);
    c.buttonText = platform.color(QPalette::ButtonText);
    c.highlight = platform.color(QPalette::Highlight);
    c.highlightedText = platform.color(QPalette::HighlightedText);
    c.placeholderText = platform.color(QPalette::PlaceholderText);
    c.toolTipBase = platform.color(QPalette::ToolTipBase);
    c.toolTipText = platform.color(QPalette::ToolTipText);
    c.link = platform.color(QPalette::Link);
    c.light = platform.color(QPalette::Light);
    c.midlight = platform.color(QPalette::Midlight);
    c.mid = platform.color(QPalette::Mid);
    c.dark = platform.color(QPalette::Dark);
    c.shadow = platform.color(QPalette::Shadow);
    return c;
}

bool ThemeColours::isDark() const
{
    return contrast::relativeLuminance(window) < 0.18;
}

} // namespace sortie::ui
