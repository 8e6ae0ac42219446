#include "MainWindow.h"

#include "AppSettings.h"
#include "ClientGraph.h"
#include "SortieUi.h"

#include <QLoggingCategory>
#include <QQmlApplicationEngine>
#include <QQuickWindow>

Q_LOGGING_CATEGORY(lcMainWindow, "sortie.ui.mainwindow")

namespace sortie::ui {

MainWindow::MainWindow(client::ClientGraph &graph, AppSettings &settings, const QString &translationsFolder)
    : m_graph(graph)
    , m_settingsWiring(graph, settings)
    , m_engine(std::make_unique<QQmlApplicationEngine>())
{
    addImportPaths(*m_engine);
    // The theme follows the operator's choice of colours, at once.
    m_theme.setScheme(Theme::schemeFromName(settings.colourScheme()));
    QObject::connect(&settings, &AppSettings::colourSchemeChanged, &m_theme,
                     [this, &settings] { m_theme.setScheme(Theme::schemeFromName(settings.colourScheme())); });
    m_translations = std::make_unique<Translations>(settings, *m_engine, translationsFolder); // before the first word is shown
    QObject::connect(m_engine.get(), &QQmlEngine::warnings, m_engine.get(), [this](const QList<QQmlError> &warnings) {
        if (m_window)
            return; // loaded: what QML says from now on is printed, not a start-up problem
        for (const QQmlError &warning : warnings)
            m_loadWarnings << warning.toString();
    });
    // Main.qml's four required properties: everything the views use comes from the graph; how they
    // look, from the theme.
    m_engine->setInitialProperties({{QStringLiteral("appSettings"), QVariant::fromValue(&settings)},
                                    {QStringLiteral("translations"), QVariant::fromValue(m_translations.get())},
                                    {QStringLiteral("graph"), QVariant::fromValue(&graph)},
                                    {QStringLiteral("theme"), QVariant::fromValue(&m_theme)}});
    m_engine->load(QUrl(QString::fromLatin1(kMainQml)));
    if (!m_engine->rootObjects().isEmpty())
        m_window = qobject_cast<QQuickWindow *>(m_engine->rootObjects().constFirst());
    if (!m_window && m_loadWarnings.isEmpty())
        m_loadWarnings << QStringLiteral("Main.qml made no window"); // i18n: not text (a load diagnostic for tests and logs)
    qCInfo(lcMainWindow).noquote() << "settings wired:" << m_settingsWiring.wiring().join(QStringLiteral("; "));
}

MainWindow::~MainWindow()
{
    // The window binds to the language (its words, the selector's list): it goes first, while the
    // translations it reads are still there.
    m_engine.reset();
    m_translations.reset();
}

QStringList MainWindow::wiring() const
{
    return m_graph.wiring() + m_settingsWiring.wiring();
}

} // namespace sortie::ui
