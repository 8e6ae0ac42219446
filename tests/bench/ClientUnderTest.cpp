#include "ClientUnderTest.h"

#include <QQuickWindow>
#include <QSignalSpy>

namespace sortie::bench {

ClientUnderTest::ClientUnderTest(bool withWindow)
    : m_storage(m_dir.filePath(QStringLiteral("settings.ini")), QSettings::IniFormat)
    , m_settings(&m_storage, &m_vault)
    , m_graph(&m_storage, {{}, m_dir.filePath(QStringLiteral("autosave")), m_dir.filePath(QStringLiteral("flightlogs")), true})
    , m_withWindow(withWindow)
{
    if (!withWindow)
        return;
    m_mainWindow = std::make_unique<ui::MainWindow>(m_graph, m_settings); // the program's window and settings wiring
    m_window = m_mainWindow->window();
    if (m_window) {
        m_window->resize(1280, 800);
        m_window->show();
    }
}

bool ClientUnderTest::logIn(const QString &address, int timeoutMs)
{
    QSignalSpy ready(&m_graph.connection(), &client::ConnectionController::ready);
    return m_graph.connection().connectToServer(address, QStringLiteral("admin"), QStringLiteral("admin")) && ready.wait(timeoutMs);
}

void ClientUnderTest::showPage(int page)
{
    if (!m_window)
        return;
    m_window->setProperty("currentPage", page);
    renderFrame();
}

void ClientUnderTest::renderFrame()
{
    if (m_window)
        m_window->grabWindow();
}

} // namespace sortie::bench
