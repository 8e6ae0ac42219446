// HciConnection against the simulated server with its fault knobs: answers out of order, a request
// that times out and its late answer, the server dropping the connection mid-request, malformed
// frames in the stream, typed server errors, unique instance ids.
#include "HciConnection.h"
#include "HciTestSupport.h"
#include "Messages.pb.h"

#include <QtTest>

#include <set>

using namespace sortie;
using hci::HciConnection;
using hci::HciError;
using hci::HciReply;
namespace pb = com::ugcs::ucs::proto;
using namespace std::chrono_literals;

namespace {

pb::AuthorizeHciRequest authorize(int clientId = -1, int major = 2)
{
    pb::AuthorizeHciRequest r;
    r.set_clientid(clientId);
    r.mutable_clientversion()->set_major(major);
    r.mutable_clientversion()->set_minor(0);
    return r;
}

bool connectTo(HciConnection &c, quint16 port)
{
    QSignalSpy connected(&c, &HciConnection::connected);
    c.connectToServer(QStringLiteral("127.0.0.1"), port);
    return connected.wait();
}

// Authorizes and logs in on a bare connection; returns the clientId.
int logIn(HciConnection &c)
{
    auto a = test::keep(c.send(authorize()));
    if (!test::finishes(a.get()) || !a->isOk())
        return -1;
    const int id = a->response<pb::AuthorizeHciResponse>().clientid();
    pb::LoginRequest login;
    login.set_clientid(id);
    login.set_userlogin("admin");
    login.set_userpassword("admin");
    auto l = test::keep(c.send(login));
    return test::finishes(l.get()) && l->isOk() ? id : -1;
}

} // namespace

class TestHciConnection : public QObject
{
    Q_OBJECT

private slots:
    void answersInAnyOrderReachTheirRequests()
    {
        test::SimServer sim;
        sim.server.faults().reverseBatch = 3;
        HciConnection c;
        QVERIFY(connectTo(c, sim.port()));
        std::vector<std::unique_ptr<HciReply>> replies;
        QList<int32_t> finishOrder;
        for (int i = 0; i < 3; ++i) {
            replies.push_back(test::keep(c.send(authorize())));
            HciReply *r = replies.back().get();
            connect(r, &HciReply::finished, this, [&finishOrder, r] { finishOrder.append(r->instanceId()); });
        }
        QTRY_COMPARE(finishOrder.size(), 3);
        // The server answered newest first, and each answer still found its own request: the server
        // created sessions in request order, so clientIds rise with instance ids.
        QCOMPARE(finishOrder, (QList<int32_t>{replies[2]->instanceId(), replies[1]->instanceId(), replies[0]->instanceId()}));
        const int first = replies[0]->response<pb::AuthorizeHciResponse>().clientid();
        for (int i = 0; i < 3; ++i) {
            QVERIFY(replies[i]->isOk());
            QCOMPARE(replies[i]->response<pb::AuthorizeHciResponse>().clientid(), first + i);
        }
    }

    void aRequestTimesOutAndItsLateAnswerIsDropped()
    {
        test::SimServer sim;
        sim.server.faults().delayMs = 400;
        HciConnection c;
        QVERIFY(connectTo(c, sim.port()));
        QSignalSpy dropped(&c, &HciConnection::frameDropped);
        auto reply = test::keep(c.send(authorize(), 100ms));
        QVERIFY(test::finishes(reply.get()));
        QCOMPARE(reply->error().kind(), HciError::Kind::Timeout);
        QCOMPARE(reply->error().message(), QStringLiteral("No answer to AuthorizeHciRequest within 100 ms"));
        QCOMPARE(c.pendingCount(), 0);
        QVERIFY(dropped.wait()); // the answer arrives after all, and nobody waits for it
        QVERIFY(dropped.first().first().toString().contains(QLatin1String("no request waits")));
        QCOMPARE(c.framesDropped(), quint64(1));
        QCOMPARE(c.state(), HciConnection::State::Connected);
    }

    void defaultTimeoutIsConfigurable()
    {
        test::SimServer sim;
        sim.server.faults().dropAnswersTo.insert(20);
        HciConnection c;
        c.setDefaultTimeout(150ms);
        QVERIFY(connectTo(c, sim.port()));
        auto reply = test::keep(c.send(authorize()));
        QVERIFY(test::finishes(reply.get()));
        QCOMPARE(reply->error().kind(), HciError::Kind::Timeout);
        QVERIFY(reply->error().message().endsWith(QLatin1String("150 ms")));
    }

    void aDropMidRequestFailsEveryPendingRequestAtOnce()
    {
        test::SimServer sim;
        HciConnection c;
        QVERIFY(connectTo(c, sim.port()));
        const int id = logIn(c);
        QVERIFY(id > 0);
        sim.server.faults().dropAnswersTo.insert(10);     // the list requests stay pending...
        sim.server.faults().disconnectOn.insert(12);      // ...until a GetObject makes the server hang up
        std::vector<std::unique_ptr<HciReply>> replies;
        for (int i = 0; i < 3; ++i) {
            pb::GetObjectListRequest r;
            r.set_clientid(id);
            r.set_objecttype("Vehicle");
            replies.push_back(test::keep(c.send(r)));
        }
        pb::GetObjectRequest get;
        get.set_clientid(id);
        get.set_objecttype("Vehicle");
        get.set_objectid(1);
        replies.push_back(test::keep(c.send(get)));
        int finishedBeforeSignal = 0;
        connect(&c, &HciConnection::disconnected, this, [&] {
            for (const auto &r : replies)
                finishedBeforeSignal += r->isFinished();
        });
        QSignalSpy disconnected(&c, &HciConnection::disconnected);
        QVERIFY(disconnected.wait());
        QCOMPARE(finishedBeforeSignal, 4);
        for (const auto &r : replies) {
            QCOMPARE(r->error().kind(), HciError::Kind::Disconnected);
            QVERIFY2(r->error().message().contains(QLatin1String("closed the connection")), qPrintable(r->error().message()));
        }
        QCOMPARE(disconnected.first().first().value<HciError>().kind(), HciError::Kind::Disconnected);
        QCOMPARE(c.pendingCount(), 0);
    }

    void malformedFramesAreDroppedAndTheStreamGoesOn()
    {
        test::SimServer sim;
        sim.server.faults().malformedBeforeAnswers = 5; // one of each kind
        HciConnection c;
        QVERIFY(connectTo(c, sim.port()));
        QStringList reasons;
        connect(&c, &HciConnection::frameDropped, this, [&](const QString &why) { reasons.append(why); });
        std::vector<std::unique_ptr<HciReply>> replies;
        for (int i = 0; i < 5; ++i)
            replies.push_back(test::keep(c.send(authorize())));
        for (const auto &r : replies) {
            QVERIFY(test::finishes(r.get()));
            QVERIFY2(r->isOk(), qPrintable(r->error().toString()));
        }
        QCOMPARE(c.framesDropped(), quint64(5));
        QCOMPARE(reasons.size(), 5);
        for (const char *why : {"bad signature", "unsupported version", "unknown message type", "invalid protobuf payload",
                                "missing required fields"})
            QVERIFY2(!reasons.filter(QLatin1String(why)).isEmpty(), why);
    }

    void serverErrorsAreTyped()
    {
        test::SimServer sim;
        HciConnection c;
        QVERIFY(connectTo(c, sim.port()));
        auto version = test::keep(c.send(authorize(-1, 3)));
        QVERIFY(test::finishes(version.get()));
        QCOMPARE(version->error().kind(), HciError::Kind::Version);
        QVERIFY2(version->error().message().contains(QLatin1String("2.0")), qPrintable(version->error().message()));
        QVERIFY(version->error().detail()->has_unsupportedprotocolversiondetail());

        pb::GetObjectListRequest early; // before any AuthorizeHci
        early.set_clientid(5);
        early.set_objecttype("Vehicle");
        auto refused = test::keep(c.send(early));
        QVERIFY(test::finishes(refused.get()));
        QCOMPARE(refused->error().kind(), HciError::Kind::Server);
        QVERIFY(refused->error().message().contains(QLatin1String("AuthorizeHciRequest first")));
    }

    void unimplementedRequestsGetANamedError()
    {
        test::SimServer sim;
        HciConnection c;
        QVERIFY(connectTo(c, sim.port()));
        const int id = logIn(c);
        QVERIFY(id > 0);
        // The simulator serves no elevation tiles (profiles and raster values, yes).
        pb::GetElevationTilesRequest tiles;
        tiles.set_clientid(id);
        tiles.set_minlatitude(0.99);
        tiles.set_minlongitude(0.42);
        tiles.set_maxlatitude(0.995);
        tiles.set_maxlongitude(0.425);
        auto reply = test::keep(c.send(tiles));
        QVERIFY(test::finishes(reply.get()));
        QVERIFY2(reply->error().message().contains(QLatin1String("GetElevationTilesRequest")), qPrintable(reply->error().message()));
    }

    void requestsThatCannotGoOutFailWithAReason()
    {
        HciConnection c;
        auto notConnected = test::keep(c.send(authorize()));
        QVERIFY(!notConnected->isFinished());
        QVERIFY(test::finishes(notConnected.get()));
        QCOMPARE(notConnected->error().kind(), HciError::Kind::Disconnected);

        test::SimServer sim;
        QVERIFY(connectTo(c, sim.port()));
        pb::LoginRequest incomplete; // no clientId, no password
        incomplete.set_userlogin("admin");
        auto bad = test::keep(c.send(incomplete));
        QVERIFY(test::finishes(bad.get()));
        QCOMPARE(bad->error().kind(), HciError::Kind::Protocol);
        QVERIFY(bad->error().message().contains(QLatin1String("clientId")));
        pb::Vehicle notARequest;
        auto wrong = test::keep(c.send(notARequest));
        QVERIFY(test::finishes(wrong.get()));
        QCOMPARE(wrong->error().kind(), HciError::Kind::Protocol);
    }

    void instanceIdsAreUniqueAmongOutstandingRequests()
    {
        test::SimServer sim;
        sim.server.faults().reverseBatch = 200;
        HciConnection c;
        QVERIFY(connectTo(c, sim.port()));
        std::vector<std::unique_ptr<HciReply>> replies;
        std::set<int32_t> ids;
        for (int i = 0; i < 200; ++i) {
            replies.push_back(test::keep(c.send(authorize())));
            QVERIFY(replies.back()->instanceId() >= 0);
            ids.insert(replies.back()->instanceId());
        }
        QCOMPARE(ids.size(), size_t(200));
        QCOMPARE(c.pendingCount(), 200);
        QTRY_COMPARE(c.pendingCount(), 0);
        std::set<int> clients;
        for (const auto &r : replies)
            clients.insert(r->response<pb::AuthorizeHciResponse>().clientid());
        QCOMPARE(clients.size(), size_t(200));
    }
};

QTEST_MAIN(TestHciConnection)
#include "tst_hciconnection.moc"
