// The telemetry fast path gives exactly what the general protobuf parser gives: on the SDK's telemetry
// vector, on notifications with every kind of value, and on tens of thousands of mutated payloads
// (it may decline any of them, but what it accepts must equal ParseFromArray's result, byte for byte).
#include "HciFrameCodec.h"
#include "TestData.h"
#include "HciTelemetryFastPath.h"
#include "Messages.pb.h"

#include <google/protobuf/util/message_differencer.h>

#include <QtTest>

#include <fstream>
#include <random>
#include <set>
#include <sstream>

using sortie::hci::HciTelemetryFastPath;
namespace pb = com::ugcs::ucs::proto;

namespace {

std::string payloadOf(const std::string &file)
{
    std::ifstream in(std::string(sortieTestData()) + "/hci-vectors/" + file, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str().substr(16);
}

pb::Notification everyValueKind()
{
    pb::Notification n;
    n.set_subscriptionid(-7);
    auto *e = n.mutable_event()->mutable_telemetryevent();
    e->mutable_vehicle()->set_id(12);
    e->mutable_vehicle()->set_version(3);
    e->mutable_vehicle()->set_name("EMU-101");
    auto add = [e](const char *code) {
        auto *t = e->add_telemetry();
        t->set_time(-1); // a ten-byte varint
        t->mutable_telemetryfield()->set_code(code);
        t->mutable_telemetryfield()->set_id(4);
        t->mutable_telemetryfield()->set_semantic(pb::S_ANY);
        t->mutable_telemetryfield()->set_subsystem(pb::S_GIMBAL);
        t->mutable_telemetryfield()->set_subsystemid(2);
        return t->mutable_value();
    };
    add("b")->set_boolvalue(true);
    add("i")->set_intvalue(-123456);
    add("l")->set_longvalue(INT64_MIN);
    add("f")->set_floatvalue(-0.0f);
    add("d")->set_doublevalue(std::numeric_limits<double>::quiet_NaN());
    add("s")->set_stringvalue("AUTO");
    add("x")->set_bytesvalue(std::string("\0\xff\x01", 3));
    auto *v = add("t");
    v->set_id(1);
    v->set_version(2);
    v->set_tag("tagged");
    e->add_telemetry(); // an empty Telemetry
    return n;
}

// Parses `payload` both ways; the fast path may decline, but must never disagree.
bool agree(const std::string &payload, pb::Notification &reused, bool *accepted)
{
    pb::Notification general;
    // ParseFromArray, without its log line for each incomplete message.
    const bool generalOk = general.ParsePartialFromArray(payload.data(), int(payload.size())) && general.IsInitialized();
    *accepted = HciTelemetryFastPath::parse(payload, &reused);
    if (!*accepted)
        return true;
    if (!generalOk)
        return false;
    // Same presence, same values, same order: the same bytes (NaN included, which == would not equal).
    return reused.SerializeAsString() == general.SerializeAsString();
}

} // namespace

class TestHciFastPath : public QObject
{
    Q_OBJECT

private slots:
    // The fast path reports what it built as complete after checking only Notification's own two
    // required fields. That holds while no message it builds (everything below Notification on the
    // telemetry path, whichever fields it reads) has a required field: walk the schema and fail if one
    // appears, with its name.
    void noRequiredFieldBelowNotification()
    {
        using google::protobuf::Descriptor;
        // The sub-message fields the fast path enters, from Notification down.
        const std::set<std::pair<std::string, int>> entered = {
            {"com.ugcs.ucs.proto.Notification", pb::Notification::kEventFieldNumber},
            {"com.ugcs.ucs.proto.EventWrapper", pb::EventWrapper::kTelemetryEventFieldNumber},
            {"com.ugcs.ucs.proto.TelemetryEvent", pb::TelemetryEvent::kVehicleFieldNumber},
            {"com.ugcs.ucs.proto.TelemetryEvent", pb::TelemetryEvent::kTelemetryFieldNumber},
            {"com.ugcs.ucs.proto.Telemetry", pb::Telemetry::kValueFieldNumber},
            {"com.ugcs.ucs.proto.Telemetry", pb::Telemetry::kTelemetryFieldFieldNumber},
        };
        std::vector<const Descriptor *> below;
        std::vector<const Descriptor *> todo = {pb::Notification::descriptor()};
        while (!todo.empty()) {
            const Descriptor *d = todo.back();
            todo.pop_back();
            for (int i = 0; i < d->field_count(); ++i) {
                const auto *f = d->field(i);
                if (f->message_type() && entered.count({d->full_name(), f->number()})) {
                    below.push_back(f->message_type());
                    todo.push_back(f->message_type());
                }
            }
        }
        QCOMPARE(int(below.size()), 6); // EventWrapper, TelemetryEvent, Vehicle, Telemetry, Value, TelemetryField
        QStringList required;
        for (const Descriptor *d : below)
            for (int i = 0; i < d->field_count(); ++i)
                if (d->field(i)->is_required())
                    required << QString::fromStdString(d->field(i)->full_name());
        QVERIFY2(required.isEmpty(), qPrintable("required below Notification: " + required.join(", ")
                                               + " (the telemetry fast path cannot check completeness)"));
        // Notification's own required fields are exactly the two the fast path checks.
        QStringList top;
        for (int i = 0; i < pb::Notification::descriptor()->field_count(); ++i)
            if (pb::Notification::descriptor()->field(i)->is_required())
                top << QString::fromStdString(pb::Notification::descriptor()->field(i)->name());
        QCOMPARE(top, QStringList({"subscriptionId", "event"}));
    }

    // The build ties each field number the fast path reads to the schema (static_asserts); this ties
    // each one's type, which decides the wire encoding the fast path expects.
    void everyFieldItReadsHasTheTypeItExpects()
    {
        using F = google::protobuf::FieldDescriptor;
        struct Expect { const google::protobuf::Descriptor *message; int number; F::Type type; bool repeated; };
        const Expect expected[] = {
            {pb::Notification::descriptor(), 1, F::TYPE_INT32, false},
            {pb::Notification::descriptor(), 2, F::TYPE_MESSAGE, false},
            {pb::EventWrapper::descriptor(), 3, F::TYPE_MESSAGE, false},
            {pb::TelemetryEvent::descriptor(), 1, F::TYPE_MESSAGE, false},
            {pb::TelemetryEvent::descriptor(), 3, F::TYPE_MESSAGE, true},
            {pb::Vehicle::descriptor(), 1, F::TYPE_INT32, false},
            {pb::Vehicle::descriptor(), 2, F::TYPE_INT32, false},
            {pb::Vehicle::descriptor(), 5, F::TYPE_STRING, false},
            {pb::Vehicle::descriptor(), 6, F::TYPE_STRING, false},
            {pb::Telemetry::descriptor(), 1, F::TYPE_MESSAGE, false},
            {pb::Telemetry::descriptor(), 2, F::TYPE_INT64, false},
            {pb::Telemetry::descriptor(), 3, F::TYPE_MESSAGE, false},
            {pb::TelemetryField::descriptor(), 1, F::TYPE_INT32, false},
            {pb::TelemetryField::descriptor(), 2, F::TYPE_STRING, false},
            {pb::TelemetryField::descriptor(), 3, F::TYPE_ENUM, false},
            {pb::TelemetryField::descriptor(), 4, F::TYPE_ENUM, false},
            {pb::TelemetryField::descriptor(), 5, F::TYPE_INT32, false},
            {pb::Value::descriptor(), 1, F::TYPE_INT32, false},
            {pb::Value::descriptor(), 2, F::TYPE_INT32, false},
            {pb::Value::descriptor(), 3, F::TYPE_BOOL, false},
            {pb::Value::descriptor(), 4, F::TYPE_INT32, false},
            {pb::Value::descriptor(), 5, F::TYPE_INT64, false},
            {pb::Value::descriptor(), 6, F::TYPE_FLOAT, false},
            {pb::Value::descriptor(), 7, F::TYPE_DOUBLE, false},
            {pb::Value::descriptor(), 8, F::TYPE_STRING, false},
            {pb::Value::descriptor(), 9, F::TYPE_STRING, false},
            {pb::Value::descriptor(), 11, F::TYPE_BYTES, false},
        };
        for (const Expect &e : expected) {
            const F *f = e.message->FindFieldByNumber(e.number);
            QVERIFY2(f, qPrintable(QString::fromStdString(e.message->name()) + " has no field " + QString::number(e.number)));
            QVERIFY2(f->type() == e.type && f->is_repeated() == e.repeated && !f->is_packed(),
                     qPrintable(QString::fromStdString(f->full_name()) + " changed type: the fast path reads it as before"));
        }
    }

    void takesTheSdkTelemetryVector()
    {
        const std::string payload = payloadOf("029-Notification.bin");
        pb::Notification fast, general;
        QVERIFY(HciTelemetryFastPath::parse(payload, &fast));
        QVERIFY(general.ParseFromString(payload));
        QVERIFY(google::protobuf::util::MessageDifferencer::Equals(fast, general));
        QCOMPARE(fast.SerializeAsString(), payload); // and it round-trips byte for byte
    }

    void takesEveryKindOfValue()
    {
        const pb::Notification n = everyValueKind();
        const std::string payload = n.SerializeAsString();
        pb::Notification fast;
        QVERIFY(HciTelemetryFastPath::parse(payload, &fast));
        QCOMPARE(fast.SerializeAsString(), payload);
        QVERIFY(std::isnan(fast.event().telemetryevent().telemetry(4).value().doublevalue()));
        QCOMPARE(fast.event().telemetryevent().telemetry(0).time(), int64_t(-1));
    }

    void declinesWhatItDoesNotKnow()
    {
        pb::Notification fast;
        QVERIFY(!HciTelemetryFastPath::parse(payloadOf("030-Notification.bin"), &fast)); // a CommandEvent
        QVERIFY(!HciTelemetryFastPath::parse(payloadOf("042-Notification.bin"), &fast)); // an object event
        pb::Notification n = everyValueKind();
        n.mutable_event()->mutable_telemetryevent()->mutable_telemetry(0)->mutable_value()->add_listvalue()->set_intvalue(1);
        QVERIFY(!HciTelemetryFastPath::parse(n.SerializeAsString(), &fast));
        n = everyValueKind();
        n.mutable_event()->mutable_telemetryevent()->mutable_vehicle()->set_serialnumber("S1"); // a full Vehicle
        QVERIFY(!HciTelemetryFastPath::parse(n.SerializeAsString(), &fast));
        n = everyValueKind();
        n.mutable_event()->mutable_telemetryevent()->mutable_vehicle()->mutable_unknown_fields()->AddVarint(100, 1);
        QVERIFY(!HciTelemetryFastPath::parse(n.SerializeAsString(), &fast)); // unknown field 100
        // A sub-message twice is merged by protobuf: left to it.
        const std::string twice = everyValueKind().SerializeAsString() + pb::Notification(everyValueKind()).SerializeAsString();
        QVERIFY(!HciTelemetryFastPath::parse(twice, &fast));
        // An unknown enum value is kept as an unknown field by proto2: left to it.
        std::string payload = payloadOf("029-Notification.bin");
        const auto at = payload.find(std::string("\x18\x02", 2)); // semantic S_LATITUDE
        QVERIFY(at != std::string::npos);
        payload[at + 1] = 0x63; // 99: no such Semantic
        QVERIFY(!HciTelemetryFastPath::parse(payload, &fast));
        // No subscriptionId: incomplete, so the decoder drops it as the general path would.
        n = everyValueKind();
        n.clear_subscriptionid();
        QVERIFY(!HciTelemetryFastPath::parse(n.SerializePartialAsString(), &fast));
    }

    void neverDisagreesOnMutatedPayloads()
    {
        const std::vector<std::string> seeds = {payloadOf("029-Notification.bin"), everyValueKind().SerializeAsString()};
        std::mt19937 random(20240611);
        pb::Notification reused; // reused across cases, as the decoder does
        int accepted = 0, cases = 0;
        for (const std::string &seed : seeds) {
            for (int i = 0; i < 20000; ++i) {
                std::string p = seed;
                const int edits = 1 + int(random() % 3);
                for (int k = 0; k < edits && !p.empty(); ++k) {
                    const size_t at = random() % p.size();
                    switch (random() % 4) {
                    case 0: p[at] = char(random()); break;                       // any byte
                    case 1: p[at] = char(p[at] ^ (1 << (random() % 8))); break;  // one bit
                    case 2: p.erase(at, 1 + random() % 4); break;                // lose bytes
                    default: p.insert(at, 1, char(random())); break;             // gain one
                    }
                }
                if (random() % 8 == 0)
                    p = p.substr(0, random() % (p.size() + 1)); // truncated
                bool took = false;
                QVERIFY2(agree(p, reused, &took), QByteArray::fromStdString(p).toHex().constData());
                accepted += took;
                ++cases;
            }
        }
        // Many mutations stay well-formed telemetry: the comparison above really ran.
        qInfo("the fast path took %d of %d mutated payloads", accepted, cases);
        QVERIFY(accepted > cases / 20);
    }

    void theDecoderGivesTheSameFramesEitherWay()
    {
        std::string stream;
        for (int i = 0; i < 50; ++i)
            sortie::hci::appendHciFrame(stream, -1, everyValueKind());
        std::string vector;
        std::ifstream in(std::string(sortieTestData()) + "/hci-vectors/stream-bad-frames.bin", std::ios::binary);
        std::stringstream s;
        s << in.rdbuf();
        stream += s.str();
        auto run = [&](bool fast) {
            sortie::hci::HciFrameDecoder decoder;
            decoder.setFastPath(fast);
            decoder.feed(stream);
            std::string out;
            while (auto r = decoder.next()) {
                if (auto *f = std::get_if<sortie::hci::HciFrame>(&*r)) {
                    out += std::to_string(f->offset) + ':' + f->message->SerializeAsString() + ';';
                    decoder.recycle(std::move(f->message));
                } else {
                    out += std::to_string(std::get<sortie::hci::HciDroppedFrame>(*r).offset) + "X;";
                }
            }
            return out;
        };
        QCOMPARE(run(true), run(false));
    }
};

QTEST_APPLESS_MAIN(TestHciFastPath)
#include "tst_hcifastpath.moc"
