#pragma once

#include <QLocale>
#include <QObject>
#include <QTranslator>
#include <QStringList>
#include <QtQml/qqmlregistration.h>

#include <memory>

class QQmlEngine;

namespace sortie::ui {

class AppSettings;

// Sortie in the operator's language, switched without a restart. Owns the translators: Sortie's own
// (sortie_<code>.qm, compiled from resources/i18n/*.ts into the program's resources) and Qt's
// (qtbase_<code>.qm from Qt's translations folder, when the system has them). It follows
// AppSettings::language; on a change it installs the new translators, makes the language's locale
// the default QLocale (the decimal separator and the dates DisplayUnits and the views format with)
// and retranslates the engine's qsTr() bindings. The QEvent::LanguageChange the translators' change
// sends lets C++ models re-emit the words they hold.
class Translations : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("Translations is created by the application")
    // What the language selector offers, in one order: the codes ("" for the system's first, then
    // English and every compiled translation) and their names, each in its own language ("Deutsch",
    // "Українська"); the one the settings ask for; chooseLanguage(index) asks for another.
    Q_PROPERTY(QStringList languageCodes READ languageCodes NOTIFY changed)
    Q_PROPERTY(QStringList languageNames READ languageNames NOTIFY changed)
    Q_PROPERTY(int chosenLanguage READ chosenLanguage NOTIFY changed)
    // The language in use: what the settings ask for ("" for the system's), resolved ("de", "en").
    Q_PROPERTY(QString active READ active NOTIFY changed)

public:
    static constexpr auto kBuiltIn = ":/i18n";

    // `folder` holds sortie_<code>.qm (the tests bring their own). The settings and the engine must
    // outlive this object. The settings' language is applied at once.
    Translations(AppSettings &settings, QQmlEngine &engine, const QString &folder = QString::fromLatin1(kBuiltIn),
                 QObject *parent = nullptr);
    ~Translations() override;

    QStringList languageCodes() const;
    QStringList languageNames() const;
    int chosenLanguage() const;  // its index in languageCodes; the system's when it asks for none there
    Q_INVOKABLE void chooseLanguage(int index);
    QString active() const { return m_active; }
    // The language codes with a compiled translation in the folder ("de", "es", "uk").
    QStringList translated() const;
    // The locale a settings value stands for: "" is the system's.
    static QLocale localeFor(const QString &code);

signals:
    void changed();

private:
    void apply();

    AppSettings &m_settings;
    QQmlEngine &m_engine;
    QString m_folder;
    QString m_requested;   // the settings' value last applied
    QString m_active;
    std::unique_ptr<QTranslator> m_sortie;
    std::unique_ptr<QTranslator> m_qt;
    std::unique_ptr<QTranslator> m_englishPlurals; // "1 waypoint", "2 waypoints": while the words are English
};

} // namespace sortie::ui
