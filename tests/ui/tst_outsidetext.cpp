// Text from outside is shown as text (issue 36): a zone file whose zone is named
// `<img src="http://127.0.0.1:PORT/b.png">Pier <font color=green>OK</font>` is loaded into the real
// client. The zone list shows the name literally and nothing asks the port for the image. A control
// made after the list was drawn (a Text left at Qt's default, AutoText, naming its own image) does
// fetch, which proves a rendered name would have, and that the port had time to hear it.
#include "Airspace.h"
#include "ClientWindow.h"
#include "MapView.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QQmlApplicationEngine>
#include <QQmlComponent>
#include <QQmlEngine>
#include <QQmlExpression>
#include <QQuickItem>
#include <QTcpServer>
#include <QTcpSocket>
#include <QtTest>

using namespace sortie;

namespace {

// Counts connections and the paths asked for; answers 404 so nothing is drawn from it.
class ImageTrap : public QObject
{
public:
    ImageTrap()
    {
        connect(&m_server, &QTcpServer::newConnection, this, [this] {
            while (QTcpSocket *socket = m_server.nextPendingConnection()) {
                connect(socket, &QTcpSocket::readyRead, socket, [this, socket] {
                    const QByteArray request = socket->readAll();
                    m_paths << QString::fromLatin1(request.split(' ').value(1));
                    socket->write("HTTP/1.1 404 Not Found\r\nContent-Length: 0\r\nConnection: close\r\n\r\n");
                    socket->disconnectFromHost();
                });
            }
        });
    }
    bool listen() { return m_server.listen(QHostAddress::LocalHost); }
    quint16 port() const { return m_server.serverPort(); }
    QStringList paths() const { return m_paths; }

private:
    QTcpServer m_server;
    QStringList m_paths;
};

void collectTexts(QQuickItem *item, const QString &text, QList<QQuickItem *> &found, bool whole = true)
{
    const QString shown = item->inherits("QQuickText") ? item->property("text").toString() : QString();
    if (whole ? shown == text : shown.contains(text))
        found << item;
    for (QQuickItem *child : item->childItems())
        collectTexts(child, text, found, whole);
}

} // namespace

class TestOutsideText : public QObject
{
    Q_OBJECT

private slots:
    void aZoneNamedInHtmlIsShownAsTextAndFetchesNothing()
    {
        ImageTrap trap;
        QVERIFY(trap.listen());
        const QString name = QStringLiteral("<img src=\"http://127.0.0.1:%1/zone.png\">Pier <font color=green>OK</font>").arg(trap.port());
        test::ClientWindow client;
        QVERIFY2(client.isReady(), qPrintable(client.error()));
        QVERIFY(client.logIn());
        QTemporaryDir dir;
        QFile file(dir.filePath(QStringLiteral("zones.geojson")));
        QVERIFY(file.open(QIODevice::WriteOnly));
        QJsonObject properties{{QStringLiteral("name"), name}};
        const QJsonArray ring{QJsonArray{24.10, 56.95}, QJsonArray{24.11, 56.95}, QJsonArray{24.11, 56.96}, QJsonArray{24.10, 56.95}};
        QJsonArray rings; // appended, not braced: QJsonArray{ring} is a copy of ring for clang, a list of it for g++
        rings.append(ring);
        const QJsonObject feature{{QStringLiteral("type"), QStringLiteral("Feature")}, {QStringLiteral("properties"), properties},
                                  {QStringLiteral("geometry"), QJsonObject{{QStringLiteral("type"), QStringLiteral("Polygon")},
                                                                           {QStringLiteral("coordinates"), rings}}}};
        file.write(QJsonDocument(QJsonObject{{QStringLiteral("type"), QStringLiteral("FeatureCollection")},
                                             {QStringLiteral("features"), QJsonArray{feature}}}).toJson());
        file.close();
        QVERIFY(client.graph().airspace().loadFile(file.fileName()));
        QVERIFY2(client.graph().airspace().problems().isEmpty(), qPrintable(client.graph().airspace().problems().join(QLatin1Char('\n'))));
        client.showPage(1);
        QQuickItem *panel = client.find(QStringLiteral("zonePanel"));
        QVERIFY(panel);
        panel->setVisible(true); // as the "Zones" button opens it

        // The zone list's label holds the name as it is, in plain text, once the list has made it.
        QList<QQuickItem *> labels;
        QTRY_VERIFY2_WITH_TIMEOUT((labels.clear(), collectTexts(client.window()->contentItem(), name, labels), !labels.isEmpty()),
                                  "the zone's name is not shown anywhere", 30000);
        for (QQuickItem *label : labels) {
            QCOMPARE(label->property("textFormat").toInt(), 0); // Text.PlainText
            QVERIFY(label->isVisible());
        }
        QVERIFY(test::waitForFrame(client.window()));

        // Under the mouse on the map, the zone's tool tip names it as text too.
        auto *map = client.page("missionPage")->property("map").value<ui::MapView *>();
        QVERIFY(map);
        map->fitBounds(56.95, 24.10, 56.96, 24.11, 80);
        QVERIFY(test::waitForFrame(client.window()));
        const QPointF inside = map->mapToScene(map->fromCoordinate(QGeoCoordinate(56.952, 24.108)));
        QTest::mouseMove(client.window(), inside.toPoint());
        QList<QQuickItem *> tips;
        QTRY_VERIFY2_WITH_TIMEOUT((tips.clear(), collectTexts(client.window()->contentItem(), name, tips, false), tips.size() > labels.size()),
                                  "no tool tip names the zone under the mouse", 10000);
        for (QQuickItem *tip : tips)
            QCOMPARE(tip->property("textFormat").toInt(), 0); // Text.PlainText
        QVERIFY(test::waitForFrame(client.window()));

        // The tool tip every control attaches (`ToolTip.text: …`) is one the engine shares: plain text as well.
        QQmlExpression shared(qmlContext(client.find(QStringLiteral("zonePanel"))), client.find(QStringLiteral("zonePanel")),
                              QStringLiteral("ToolTip.toolTip.contentItem.textFormat"));
        QCOMPARE(shared.evaluate().toInt(), 0);
        QVERIFY2(!shared.hasError(), qPrintable(shared.error().toString()));

        // The control: a Text at Qt's default in the same engine and window asks for its image (its own
        // URL, so that Qt's image cache cannot answer it from a request the zone list made).
        QQmlComponent component(&client.mainWindow().engine());
        component.setData("import QtQuick\nText { property string shown; text: shown }", QUrl());
        std::unique_ptr<QObject> control(component.createWithInitialProperties(
            {{QStringLiteral("shown"), QString(name).replace(QStringLiteral("/zone.png"), QStringLiteral("/control.png"))}}));
        QVERIFY2(control, qPrintable(component.errorString()));
        qobject_cast<QQuickItem *>(control.get())->setParentItem(client.window()->contentItem());
        QTRY_VERIFY_WITH_TIMEOUT(trap.paths().contains(QStringLiteral("/control.png")), 30000);
        // The zone list was drawn before the control was made: had it asked, it would have first.
        QCOMPARE(trap.paths(), QStringList{QStringLiteral("/control.png")});
    }
};

QTEST_MAIN(TestOutsideText)
#include "tst_outsidetext.moc"
