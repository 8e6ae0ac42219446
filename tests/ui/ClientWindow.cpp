#include "ClientWindow.h"

#include "SimVciListener.h"

#include <QSignalSpy>
#include <QTest>

#include <algorithm>
#include <functional>

namespace sortie::test {

ClientWindow::ClientWindow(Options options)
{
    sim::SimWorld::Config config;
    config.users = {{0, QStringLiteral("admin"), QStringLiteral("admin"), true}};
    config.mannedTraffic = options.mannedTraffic;
    m_world = std::make_unique<sim::SimWorld>(config);
    m_server = std::make_unique<sim::HciServer>(*m_world);
    m_server->setUploadStepMs(options.uploadStepMs);
    m_server->setTls(options.hciTls);
    if (!m_server->listen(QHostAddress::LocalHost, 0)) {
        m_error = QStringLiteral("the simulated server cannot listen");
        return;
    }
    sim::SimVciFleetOptions vci;
    vci.count = options.vciVehicles;
    vci.firstPort = 0;
    vci.vehicle.timeScale = options.vciTimeScale;
    if (options.vciEnergy)
        vci.vehicle.energy = *options.vciEnergy;
    if (options.vciHome.isValid()) {
        vci.vehicle.homeLatitude = options.vciHome.latitude();
        vci.vehicle.homeLongitude = options.vciHome.longitude();
    }
    m_vci = std::make_unique<sim::SimVciFleet>(vci);
    if (!m_vci->start(&m_error))
        return;
    if (options.beforeClient)
        options.beforeClient(*this);
    m_storage = std::make_unique<QSettings>(m_dir.filePath(QStringLiteral("sortie.ini")), QSettings::IniFormat);
    m_settings = std::make_unique<ui::AppSettings>(m_storage.get(), &m_vault);
    // The program's graph, with the fixture's own folders where the program has the operator's.
    client::ClientGraph::Options graph;
    graph.autosaveDirectory = options.autosaveDirectory.isEmpty() ? m_dir.filePath(QStringLiteral("autosave"))
                                                                   : options.autosaveDirectory;
    graph.flightLogDirectory = m_dir.filePath(QStringLiteral("flightlogs"));
    graph.zoneFeedDirectory = m_dir.filePath(QStringLiteral("zone-feeds"));
    graph.checklistDirectory = options.checklistDirectory.isEmpty() ? m_dir.filePath(QStringLiteral("checklists")) : options.checklistDirectory;
    m_graph = std::make_unique<client::ClientGraph>(m_storage.get(), graph);
    // The program's window and settings wiring (ui::MainWindow), with the fixture's translations if it has its own.
    m_mainWindow = std::make_unique<ui::MainWindow>(*m_graph, *m_settings,
                                                    options.translationsFolder.isEmpty() ? QString::fromLatin1(ui::Translations::kBuiltIn)
                                                                                         : options.translationsFolder);
    if (!m_mainWindow->window() || !m_mainWindow->loadWarnings().isEmpty()) {
        m_error = QStringLiteral("Main.qml did not load cleanly: ") + m_mainWindow->loadWarnings().join(QLatin1Char('\n'));
        return;
    }
    m_window = m_mainWindow->window();
    m_window->resize(options.size);
    m_window->show();
    if (!QTest::qWaitForWindowExposed(m_window)) {
        m_error = QStringLiteral("the window was not exposed");
        m_window = nullptr;
        return;
    }
    if (options.activate) {
        m_window->requestActivate();
        if (!QTest::qWaitForWindowActive(m_window)) {
            m_error = QStringLiteral("the window did not become active");
            m_window = nullptr;
        }
    }
}

ClientWindow::~ClientWindow()
{
    m_mainWindow.reset();
    m_graph.reset();
    m_vci.reset();
    m_server.reset();
    m_world.reset();
}

bool ClientWindow::logIn()
{
    QSignalSpy ready(&m_graph->connection(), &client::ConnectionController::ready);
    if (!m_graph->connection().connectToServer(QStringLiteral("127.0.0.1:%1").arg(m_server->port()), QStringLiteral("admin"),
                                       QStringLiteral("admin")))
        return false;
    return ready.wait(10000) || m_graph->connection().isReady();
}

bool ClientWindow::openDemoRoute()
{
    auto *routes = m_graph->missions().routes();
    if (!QTest::qWaitFor([&] { return routes->rowCount() > 0 && !m_graph->missions().isBusy(); }, 10000))
        return false;
    const int id = routes->objectIdAt(0);
    m_graph->missions().openRoute(id);
    return QTest::qWaitFor([&] { return m_graph->missions().routeId() == id && m_graph->missions().document()->model()->rowCount() > 0; }, 10000);
}

bool ClientWindow::addVciVehicles()
{
    const int before = m_graph->fleet()->count();
    for (const auto &listener : m_vci->listeners())
        if (!m_graph->fleet()->addVciVehicle(QStringLiteral("tcp://127.0.0.1:%1").arg(listener->port())))
            return false;
    return QTest::qWaitFor([&] {
        for (int row = before; row < m_graph->fleet()->count(); ++row)
            if (!m_graph->fleet()->vehicleAt(row)->position().isValid())
                return false;
        return m_graph->fleet()->count() == before + int(m_vci->listeners().size());
    }, 10000);
}

void ClientWindow::showPage(int page)
{
    m_window->setProperty("currentPage", page);
}

QQuickItem *ClientWindow::waypointCell(int row, const QString &role) const
{
    QQuickItem *list = find(QStringLiteral("waypointList"));
    if (!list)
        return nullptr;
    QList<QQuickItem *> cells;
    std::function<void(QQuickItem *)> collect = [&](QQuickItem *item) {
        if (item->property("role").toString() == role && item->isVisible())
            cells.append(item);
        for (QQuickItem *child : item->childItems())
            collect(child);
    };
    collect(list);
    std::sort(cells.begin(), cells.end(), [](QQuickItem *a, QQuickItem *b) { return a->mapToScene({0, 0}).y() < b->mapToScene({0, 0}).y(); });
    return row >= 0 && row < cells.size() ? cells[row] : nullptr;
}

bool waitForFrame(QQuickWindow *window)
{
    for (int i = 0; i < 2; ++i) {
        QSignalSpy swapped(window, &QQuickWindow::frameSwapped);
        window->update();
        if (!swapped.wait(2000))
            return false;
    }
    return true;
}

} // namespace sortie::test
