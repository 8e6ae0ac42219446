#include "Translations.h"

#include <algorithm>

#include "AppSettings.h"
#include "StandardButtonWords.h"

#include <QCoreApplication>
#include <QGuiApplication>
#include <QWindow>
#include <QDir>
#include <QLibraryInfo>
#include <QLoggingCategory>
#include <QQmlEngine>

namespace sortie::ui {

Q_LOGGING_CATEGORY(lcTranslations, "sortie.ui.translations")

namespace {
const QString kPrefix = QStringLiteral("sortie_");

// "Deutsch", "Español", "Українська": the name a speaker reads, capitalised as a menu item. English
// is the source language, without a country ("American English" is what the locale would say).
QString nativeName(const QString &code)
{
    if (code == QLatin1String("en"))
        return QStringLiteral("English");
    QString name = QLocale(code).nativeLanguageName();
    if (!name.isEmpty())
        name[0] = name[0].toUpper();
    return name.isEmpty() ? code : name;
}
} // namespace

Translations::Translations(AppSettings &settings, QQmlEngine &engine, const QString &folder, QObject *parent)
    : QObject(parent)
    , m_settings(settings)
    , m_engine(engine)
    , m_folder(folder)
{
    connect(&m_settings, &AppSettings::languageChanged, this, [this] {
        if (m_settings.language() != m_requested)
            apply();
    });
    apply();
}

Translations::~Translations()
{
    // Removing them sends a LanguageChange to whatever still listens: the words fall back to English.
    if (m_sortie)
        QCoreApplication::removeTranslator(m_sortie.get());
    if (m_qt)
        QCoreApplication::removeTranslator(m_qt.get());
    if (m_englishPlurals)
        QCoreApplication::removeTranslator(m_englishPlurals.get());
}

QStringList Translations::translated() const
{
    QStringList codes;
    const QStringList files = QDir(m_folder).entryList({kPrefix + QStringLiteral("*.qm")}, QDir::Files, QDir::Name);
    for (const QString &file : files)
        codes << file.mid(kPrefix.size()).chopped(3);
    return codes;
}

QStringList Translations::languageCodes() const
{
    QStringList codes{QString(), QStringLiteral("en")};
    for (const QString &code : translated())
        if (code != QLatin1String("en"))
            codes << code;
    return codes;
}

QStringList Translations::languageNames() const
{
    QStringList names;
    for (const QString &code : languageCodes())
        names << (code.isEmpty() ? tr("System language") : nativeName(code));
    return names;
}

int Translations::chosenLanguage() const
{
    return std::max(0, int(languageCodes().indexOf(m_settings.language())));
}

void Translations::chooseLanguage(int index)
{
    const QStringList codes = languageCodes();
    if (index >= 0 && index < codes.size())
        m_settings.setLanguage(codes[index]);
}

QLocale Translations::localeFor(const QString &code)
{
    return code.isEmpty() ? QLocale::system() : QLocale(code);
}

void Translations::apply()
{
    m_requested = m_settings.language();
    const QLocale locale = localeFor(m_requested);
    // Out with the old ones first: an English choice must not keep the last language's words.
    for (auto *old : {&m_sortie, &m_qt, &m_englishPlurals}) {
        if (*old) {
            QCoreApplication::removeTranslator(old->get());
            old->reset();
        }
    }
    auto sortie = std::make_unique<QTranslator>();
    // English is the source language: no file. Another language is looked up by the locale's UI
    // languages (de_AT falls back to de).
    if (locale.language() != QLocale::English && sortie->load(locale, QStringLiteral("sortie"), QStringLiteral("_"), m_folder)) {
        QCoreApplication::installTranslator(sortie.get());
        m_sortie = std::move(sortie);
    }
    // English words have English plurals: the source says "%n waypoint(s)", sortie_en (plural forms
    // only, scripts/english-plurals.py) says "1 waypoint" and "2 waypoints".
    if (!m_sortie) {
        auto plurals = std::make_unique<QTranslator>();
        if (plurals->load(kPrefix + QStringLiteral("en"), m_folder)) {
            QCoreApplication::installTranslator(plurals.get());
            m_englishPlurals = std::move(plurals);
        }
    }
    // Qt's own words (a dialog's "Cancel"): Debian's qt6-translations-l10n. Without them those stay
    // English in a translated UI, which is said in the log, not hidden.
    auto qt = std::make_unique<QTranslator>();
    const QString qtFolder = QLibraryInfo::path(QLibraryInfo::TranslationsPath);
    if (locale.language() != QLocale::English) {
        if (qt->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"), qtFolder)) {
            QCoreApplication::installTranslator(qt.get());
            m_qt = std::move(qt);
        } else if (m_sortie) { // a language Sortie speaks: its dialogs would mix in English
            qCWarning(lcTranslations).noquote() << "Qt's own translation qtbase_" + locale.name() + ".qm is not in" << qtFolder
                                                << "(install qt6-translations-l10n): Qt's dialog buttons stay English";
        }
    }
    // Numbers and dates follow the words: a German UI writes 12,5 m. Without a translation for the
    // language asked for, the words are English, and so are the numbers, unless the system's
    // language was asked for: then its formats stay.
    const bool translatedNow = m_sortie != nullptr;
    const QLocale formats = translatedNow || m_requested.isEmpty() ? locale : QLocale(QLocale::English, QLocale::UnitedStates);
    m_active = translatedNow ? locale.name().section(QLatin1Char('_'), 0, 0) : QStringLiteral("en");
    QLocale::setDefault(formats);
    qCInfo(lcTranslations).noquote() << "language" << (m_requested.isEmpty() ? QStringLiteral("(system)") : m_requested) << "->"
                                     << m_active << (m_qt ? "with Qt's translations" : "without Qt's translations");
    m_engine.retranslate();
    // What retranslate() does not reach: the standard buttons of the dialogs already made.
    for (QWindow *window : QGuiApplication::topLevelWindows())
        rewordStandardButtons(window);
    emit changed();
}

} // namespace sortie::ui
