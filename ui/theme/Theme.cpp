#include "Theme.h"

#include "LanguageChange.h"

#include <QCoreApplication>
#include <QEvent>
#include <QFontInfo>
#include <QGuiApplication>
#include <QLoggingCategory>

#include <algorithm>

Q_LOGGING_CATEGORY(lcTheme, "sortie.ui.theme")

namespace sortie::ui {

namespace {
struct SchemeName
{
    Theme::Scheme scheme;
    const char *code;
    const char *name; // QT_TRANSLATE_NOOP: worded in the operator's language by schemes()
};
constexpr SchemeName kSchemes[] = {
    {Theme::Scheme::System, "system", QT_TRANSLATE_NOOP("sortie::ui::Theme", "System colours")},
    {Theme::Scheme::Light, "light", QT_TRANSLATE_NOOP("sortie::ui::Theme", "Light")},
    {Theme::Scheme::Dark, "dark", QT_TRANSLATE_NOOP("sortie::ui::Theme", "Dark")},
    {Theme::Scheme::Sunlight, "sunlight", QT_TRANSLATE_NOOP("sortie::ui::Theme", "Sunlight (high contrast)")},
};
} // namespace

Theme::Theme(QObject *parent)
    : QObject(parent)
    , m_colours(coloursOf(m_scheme, QGuiApplication::palette()))
{
    // System follows the platform: the application's palette changes when the desktop's does.
    if (QCoreApplication::instance())
        QCoreApplication::instance()->installEventFilter(this);
    i18n::onLanguageChange(this, [this] { emit schemesChanged(); });
}

Theme::~Theme() = default;

bool Theme::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == QCoreApplication::instance()) {
        if (event->type() == QEvent::ApplicationPaletteChange && m_scheme == Scheme::System)
            update();
        else if (event->type() == QEvent::ApplicationFontChange)
            emit fontsChanged();
    }
    return QObject::eventFilter(watched, event);
}

void Theme::setScheme(Scheme scheme)
{
    if (scheme == m_scheme)
        return;
    m_scheme = scheme;
    qCInfo(lcTheme) << "colour scheme:" << nameOf(scheme);
    emit schemeChanged();
    update();
}

void Theme::update()
{
    ThemeColours colours = coloursOf(m_scheme, QGuiApplication::palette());
    const bool same = colours == m_colours;
    m_colours = colours;
    if (!same)
        emit coloursChanged();
}

ThemeColours Theme::coloursOf(Scheme scheme, const QPalette &platform)
{
    switch (scheme) {
    case Scheme::Light: return ThemeColours::lightScheme();
    case Scheme::Dark: return ThemeColours::darkScheme();
    case Scheme::Sunlight: return ThemeColours::sunlightScheme();
    case Scheme::System: break;
    }
    return ThemeColours::fromPlatform(platform);
}

Theme::Scheme Theme::schemeFromName(const QString &name)
{
    for (const SchemeName &s : kSchemes)
        if (name == QLatin1String(s.code))
            return s.scheme;
    return Scheme::System;
}

QString Theme::nameOf(Scheme scheme)
{
    for (const SchemeName &s : kSchemes)
        if (s.scheme == scheme)
            return QString::fromLatin1(s.code);
    return QStringLiteral("system");
}

QStringList Theme::schemeCodes() const
{
    QStringList codes;
    for (const SchemeName &s : kSchemes)
        codes << QString::fromLatin1(s.code);
    return codes;
}

QStringList Theme::schemeNames() const
{
    QStringList names;
    for (const SchemeName &s : kSchemes)
        names << QCoreApplication::translate("sortie::ui::Theme", s.name);
    return names;
}

int Theme::schemeIndex() const
{
    return std::max(0, int(schemeCodes().indexOf(nameOf(scheme()))));
}

const ThemeColours &coloursOf(const Theme *theme)
{
    static const ThemeColours light = ThemeColours::lightScheme();
    return theme ? theme->colours() : light;
}

int Theme::fontSize() const
{
    // The platform's body text, and never below 14 px: read at arm's length on a field laptop.
    return std::max(14, QFontInfo(QGuiApplication::font()).pixelSize());
}

int Theme::smallFontSize() const
{
    return std::max(12, fontSize() * 5 / 6);
}

int Theme::titleFontSize() const
{
    return fontSize() * 5 / 4;
}

} // namespace sortie::ui
