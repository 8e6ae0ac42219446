// The VCI profile's fence (VciFence.h): a fence goes to JSON and back unchanged, every bad part is
// refused with its path, and the limits (items, vertices per polygon and in all) are held.
#include "VciFence.h"

#include <QtTest>

using nlohmann::json;
using namespace sortie::vci::profile;

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

Fence sampleFence()
{
    Fence f;
    FenceItem keepIn;
    keepIn.kind = FenceKind::Inclusion;
    keepIn.name = "field";
    keepIn.polygon = {{56.94 * kDeg, 24.10 * kDeg}, {56.94 * kDeg, 24.12 * kDeg}, {56.96 * kDeg, 24.12 * kDeg}, {56.96 * kDeg, 24.10 * kDeg}};
    keepIn.ceiling = FenceLimit{120, FenceReference::Home};
    FenceItem tower;
    tower.kind = FenceKind::Exclusion;
    tower.name = "mast";
    tower.center = FenceVertex{56.95 * kDeg, 24.11 * kDeg};
    tower.radius = 75.5;
    tower.floor = FenceLimit{15.25, FenceReference::Amsl};
    tower.ceiling = FenceLimit{300, FenceReference::Amsl};
    f.items = {keepIn, tower};
    f.breachAction = BreachAction::Land;
    return f;
}

std::string errorOf(const json &body)
{
    std::string error;
    const auto fence = decodeFence(body, &error);
    return fence ? std::string("(accepted)") : error;
}

} // namespace

class TestVciFence : public QObject
{
    Q_OBJECT

private slots:
    void roundTrip()
    {
        const Fence f = sampleFence();
        const json body = encodeFence(f);
        QCOMPARE(body["breachAction"], json("land"));
        QCOMPARE(body["items"][1]["circle"]["radius"], json(75.5));
        QCOMPARE(body["items"][0]["ceiling"]["reference"], json("home"));
        QVERIFY(!body["items"][0].contains("floor")); // none: from the ground
        // Through text, as the wire carries it: the same fence, to the last bit.
        std::string error;
        const auto back = decodeFence(json::parse(body.dump()), &error);
        QVERIFY2(back, error.c_str());
        QVERIFY(*back == f);
        // A GET's extra keys (version) are not the fence's business.
        json withVersion = body;
        withVersion["version"] = 3;
        QVERIFY(decodeFence(withVersion, nullptr) == f);
    }

    void emptyFenceAndDefaultAction()
    {
        const auto f = decodeFence(json{{"items", json::array()}}, nullptr);
        QVERIFY(f && f->empty());
        QCOMPARE(f->breachAction, BreachAction::Return);
        QCOMPARE(encodeFence(Fence{}), (json{{"items", json::array()}, {"breachAction", "return"}}));
    }

    void badInputNamesThePath_data()
    {
        QTest::addColumn<QByteArray>("body");
        QTest::addColumn<QByteArray>("error");
        const auto row = [](const char *tag, const char *body, const char *error) { QTest::newRow(tag) << QByteArray(body) << QByteArray(error); };
        row("not an object", "[1]", "the body must be an object with an \"items\" array");
        row("no items", "{}", "items: must be an array (empty for no fence)");
        row("action", R"({"items":[],"breachAction":"dance"})", "breachAction: must be \"return\", \"land\" or \"hold\"");
        row("kind", R"({"items":[{"kind":"maybe","circle":{"latitude":0,"longitude":0,"radius":5}}]})",
            "items[0].kind: must be \"inclusion\" or \"exclusion\"");
        row("both shapes", R"({"items":[{"kind":"inclusion","circle":{"latitude":0,"longitude":0,"radius":5},"polygon":[]}]})",
            "items[0]: must have either a \"polygon\" or a \"circle\"");
        row("two vertices", R"({"items":[{"kind":"inclusion","polygon":[{"latitude":0,"longitude":0},{"latitude":0,"longitude":0.1}]}]})",
            "items[0].polygon: must be an array of 3 or more vertices");
        row("latitude", R"({"items":[{"kind":"inclusion","polygon":[{"latitude":0,"longitude":0},{"latitude":2,"longitude":0.1},{"latitude":0.1,"longitude":0}]}]})",
            "items[0].polygon[1].latitude: must be a number of radians in [-pi/2, pi/2]");
        row("longitude", R"({"items":[{"kind":"exclusion","circle":{"latitude":0,"longitude":"east","radius":5}}]})",
            "items[0].circle.longitude: must be a number of radians in [-pi, pi]");
        row("radius", R"({"items":[{"kind":"exclusion","circle":{"latitude":0,"longitude":0,"radius":0}}]})",
            "items[0].circle.radius: must be a number of metres above 0");
        row("agl", R"({"items":[{"kind":"exclusion","circle":{"latitude":0,"longitude":0,"radius":5},"floor":{"altitude":10,"reference":"agl"}}]})",
            "items[0].floor.reference: \"agl\" is not \"amsl\" or \"home\" (AGL limits are converted by the client)");
        row("floor altitude", R"({"items":[{"kind":"exclusion","circle":{"latitude":0,"longitude":0,"radius":5},"floor":{"reference":"home"}}]})",
            "items[0].floor.altitude: must be a number of metres");
        row("upside down", R"({"items":[{"kind":"exclusion","circle":{"latitude":0,"longitude":0,"radius":5},"floor":{"altitude":50,"reference":"home"},"ceiling":{"altitude":50,"reference":"home"}}]})",
            "items[0].ceiling: must be above the floor");
        row("name", R"({"items":[{"kind":"exclusion","name":7,"circle":{"latitude":0,"longitude":0,"radius":5}}]})",
            "items[0].name: must be a string");
    }

    void badInputNamesThePath()
    {
        QFETCH(QByteArray, body);
        QFETCH(QByteArray, error);
        QCOMPARE(QByteArray::fromStdString(errorOf(json::parse(body.toStdString()))), error);
    }

    void limits()
    {
        const auto circle = [](int i) {
            return json{{"kind", "exclusion"}, {"circle", {{"latitude", 0.0}, {"longitude", i * 1e-5}, {"radius", 5.0}}}};
        };
        json items = json::array();
        for (size_t i = 0; i < kMaxFenceItems; ++i)
            items.push_back(circle(int(i)));
        QVERIFY(decodeFence(json{{"items", items}}, nullptr)); // exactly at the limit
        items.push_back(circle(0));
        QCOMPARE(errorOf(json{{"items", items}}), std::string("items: 257 items, more than the 256 a fence may hold"));

        const auto polygon = [](size_t n) {
            json ring = json::array();
            for (size_t k = 0; k < n; ++k) {
                const double a = 2 * 3.14159265358979323846 * double(k) / double(n);
                ring.push_back({{"latitude", 0.9 + 1e-4 * std::sin(a)}, {"longitude", 0.4 + 1e-4 * std::cos(a)}});
            }
            return json{{"kind", "inclusion"}, {"polygon", ring}};
        };
        QVERIFY(decodeFence(json{{"items", {polygon(kMaxPolygonVertices)}}}, nullptr));
        QCOMPARE(errorOf(json{{"items", {polygon(kMaxPolygonVertices + 1)}}}),
                 std::string("items[0].polygon: 1001 vertices, more than the 1000 a polygon may have"));
        json many = json::array();
        for (size_t i = 0; i < kMaxFenceVertices / kMaxPolygonVertices + 1; ++i)
            many.push_back(polygon(kMaxPolygonVertices));
        QCOMPARE(errorOf(json{{"items", many}}), std::string("items[20].polygon: the fence has more than the 20000 vertices it may have"));

        // The sender checks the same limits before it sends.
        Fence big;
        big.items.resize(kMaxFenceItems + 1, sampleFence().items[1]);
        QCOMPARE(fenceLimitProblem(big), std::string("257 fence items, more than the 256 a vehicle takes"));
        QCOMPARE(fenceLimitProblem(sampleFence()), std::string());
    }

    void status()
    {
        FenceStatus s;
        s.state = "breached";
        s.breaches = 2;
        s.item = 1;
        s.name = "mast";
        s.kind = "inside-exclusion";
        s.action = "land";
        s.time = 1700000000123;
        const auto back = decodeFenceStatus(json::parse(encodeFenceStatus(s).dump()));
        QVERIFY(back);
        QCOMPARE(back->state, s.state);
        QCOMPARE(back->breaches, 2);
        QCOMPARE(back->item, 1);
        QCOMPARE(back->name, s.name);
        QCOMPARE(back->kind, s.kind);
        QCOMPARE(back->action, s.action);
        QCOMPARE(back->time, s.time);
        QVERIFY(!decodeFenceStatus(json("breached")));
        QVERIFY(!decodeFenceStatus(json{{"breaches", 1}}));
    }
};

QTEST_APPLESS_MAIN(TestVciFence)
#include "tst_vcifence.moc"
