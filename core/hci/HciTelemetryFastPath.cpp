#include "HciTelemetryFastPath.h"

#include "Messages.pb.h"

#include <cstring>

namespace sortie::hci {
namespace {

enum WireType : uint32_t { kVarint = 0, kFixed64 = 1, kLength = 2, kFixed32 = 5 };

// The parsers below name fields by number, as the wire does. Each number is tied to the generated
// schema here, so a renumbered or removed field fails the build instead of silently mis-parsing.
// (tst_hcifastpath checks the rest at run time: no required field below Notification, and each
// field's type matches the wire type read here.)
static_assert(pb::Notification::kSubscriptionIdFieldNumber == 1);
static_assert(pb::Notification::kEventFieldNumber == 2);
static_assert(pb::EventWrapper::kTelemetryEventFieldNumber == 3);
static_assert(pb::TelemetryEvent::kVehicleFieldNumber == 1);
static_assert(pb::TelemetryEvent::kTelemetryFieldNumber == 3);
static_assert(pb::Vehicle::kIdFieldNumber == 1);
static_assert(pb::Vehicle::kVersionFieldNumber == 2);
static_assert(pb::Vehicle::kNameFieldNumber == 5);
static_assert(pb::Vehicle::kTailNumberFieldNumber == 6);
static_assert(pb::Telemetry::kValueFieldNumber == 1);
static_assert(pb::Telemetry::kTimeFieldNumber == 2);
static_assert(pb::Telemetry::kTelemetryFieldFieldNumber == 3);
static_assert(pb::TelemetryField::kIdFieldNumber == 1);
static_assert(pb::TelemetryField::kCodeFieldNumber == 2);
static_assert(pb::TelemetryField::kSemanticFieldNumber == 3);
static_assert(pb::TelemetryField::kSubsystemFieldNumber == 4);
static_assert(pb::TelemetryField::kSubsystemIdFieldNumber == 5);
static_assert(pb::Value::kIdFieldNumber == 1);
static_assert(pb::Value::kVersionFieldNumber == 2);
static_assert(pb::Value::kBoolValueFieldNumber == 3);
static_assert(pb::Value::kIntValueFieldNumber == 4);
static_assert(pb::Value::kLongValueFieldNumber == 5);
static_assert(pb::Value::kFloatValueFieldNumber == 6);
static_assert(pb::Value::kDoubleValueFieldNumber == 7);
static_assert(pb::Value::kStringValueFieldNumber == 8);
static_assert(pb::Value::kTagFieldNumber == 9);
static_assert(pb::Value::kListValueFieldNumber == 10); // left to the general parser
static_assert(pb::Value::kBytesValueFieldNumber == 11);

// A bounded cursor over wire-format bytes. Every read checks the bounds; a varint longer than ten
// bytes fails, as it does in protobuf.
struct Reader
{
    const uint8_t *p;
    const uint8_t *end;

    bool atEnd() const { return p == end; }

    bool varint(uint64_t &value)
    {
        if (p < end && *p < 0x80) {
            value = *p++;
            return true;
        }
        if (end - p >= 10) {
            // Ten bytes are there: no bounds check per byte (timestamps take six).
            uint64_t result = 0;
            for (int i = 0; i < 10; ++i) {
                const uint8_t byte = p[i];
                result |= uint64_t(byte & 0x7f) << (7 * i);
                if (byte < 0x80) {
                    p += i + 1;
                    value = result;
                    return true;
                }
            }
            return false;
        }
        uint64_t result = 0;
        for (int shift = 0; shift < 70; shift += 7) {
            if (p == end)
                return false;
            const uint8_t byte = *p++;
            result |= uint64_t(byte & 0x7f) << shift;
            if (byte < 0x80) {
                value = result;
                return true;
            }
        }
        return false;
    }

    bool tag(uint32_t &field, uint32_t &wire)
    {
        uint64_t t;
        if (p < end && *p < 0x80) {
            t = *p++; // every tag of these messages fits one byte
        } else if (!varint(t) || t > 0xffffffffu) {
            return false;
        }
        field = uint32_t(t >> 3);
        wire = uint32_t(t & 7);
        return field != 0;
    }

    bool fixed32(uint32_t &value)
    {
        if (end - p < 4)
            return false;
        std::memcpy(&value, p, 4); // little-endian on the wire and on every platform we build for
        p += 4;
        return true;
    }

    bool fixed64(uint64_t &value)
    {
        if (end - p < 8)
            return false;
        std::memcpy(&value, p, 8);
        p += 8;
        return true;
    }

    bool slice(Reader &inner)
    {
        uint64_t length;
        if (!varint(length) || length > uint64_t(end - p))
            return false;
        inner = {p, p + length};
        p += length;
        return true;
    }

    bool string(std::string *out)
    {
        Reader s{};
        if (!slice(s))
            return false;
        out->assign(reinterpret_cast<const char *>(s.p), size_t(s.end - s.p));
        return true;
    }
};

// Each parser below handles exactly its message's fields and wire types; anything else returns false.
// Scalars seen twice keep the last value, as protobuf does; a sub-message seen twice would be merged
// by protobuf, so it gives up instead.

bool parseValue(Reader r, pb::Value *v)
{
    uint32_t field, wire;
    while (!r.atEnd()) {
        if (!r.tag(field, wire))
            return false;
        uint64_t n;
        if (wire == kVarint) {
            if (!r.varint(n))
                return false;
            switch (field) {
            case 1: v->set_id(int32_t(n)); break;
            case 2: v->set_version(int32_t(n)); break;
            case 3: v->set_boolvalue(n != 0); break;
            case 4: v->set_intvalue(int32_t(n)); break;
            case 5: v->set_longvalue(int64_t(n)); break;
            default: return false;
            }
        } else if (wire == kFixed32 && field == 6) {
            uint32_t bits;
            float f;
            if (!r.fixed32(bits))
                return false;
            std::memcpy(&f, &bits, 4);
            v->set_floatvalue(f);
        } else if (wire == kFixed64 && field == 7) {
            uint64_t bits;
            double d;
            if (!r.fixed64(bits))
                return false;
            std::memcpy(&d, &bits, 8);
            v->set_doublevalue(d);
        } else if (wire == kLength && field == 8) {
            if (!r.string(v->mutable_stringvalue()))
                return false;
        } else if (wire == kLength && field == 9) {
            if (!r.string(v->mutable_tag()))
                return false;
        } else if (wire == kLength && field == 11) {
            if (!r.string(v->mutable_bytesvalue()))
                return false;
        } else {
            return false; // listValue (10) and anything unknown: the general parser's job
        }
    }
    return true;
}

bool parseField(Reader r, pb::TelemetryField *f)
{
    uint32_t field, wire;
    while (!r.atEnd()) {
        if (!r.tag(field, wire))
            return false;
        if (wire == kLength && field == 2) {
            if (!r.string(f->mutable_code()))
                return false;
            continue;
        }
        uint64_t n;
        if (wire != kVarint || !r.varint(n))
            return false;
        switch (field) {
        case 1: f->set_id(int32_t(n)); break;
        case 3:
            if (!pb::Semantic_IsValid(int32_t(n)))
                return false; // proto2 keeps unknown enum values as unknown fields
            f->set_semantic(pb::Semantic(int32_t(n)));
            break;
        case 4:
            if (!pb::Subsystem_IsValid(int32_t(n)))
                return false;
            f->set_subsystem(pb::Subsystem(int32_t(n)));
            break;
        case 5: f->set_subsystemid(int32_t(n)); break;
        default: return false;
        }
    }
    return true;
}

bool parseTelemetry(Reader r, pb::Telemetry *t)
{
    uint32_t field, wire;
    while (!r.atEnd()) {
        if (!r.tag(field, wire))
            return false;
        Reader inner{};
        if (wire == kLength && field == 1) {
            if (t->has_value() || !r.slice(inner) || !parseValue(inner, t->mutable_value()))
                return false;
        } else if (wire == kLength && field == 3) {
            if (t->has_telemetryfield() || !r.slice(inner) || !parseField(inner, t->mutable_telemetryfield()))
                return false;
        } else if (wire == kVarint && field == 2) {
            uint64_t n;
            if (!r.varint(n))
                return false;
            t->set_time(int64_t(n));
        } else {
            return false;
        }
    }
    return true;
}

bool parseVehicle(Reader r, pb::Vehicle *v)
{
    uint32_t field, wire;
    while (!r.atEnd()) {
        if (!r.tag(field, wire))
            return false;
        if (wire == kLength && field == 5) {
            if (!r.string(v->mutable_name()))
                return false;
        } else if (wire == kLength && field == 6) {
            if (!r.string(v->mutable_tailnumber()))
                return false;
        } else if (wire == kVarint && (field == 1 || field == 2)) {
            uint64_t n;
            if (!r.varint(n))
                return false;
            field == 1 ? v->set_id(int32_t(n)) : v->set_version(int32_t(n));
        } else {
            return false; // a full Vehicle: rare in telemetry, left to the general parser
        }
    }
    return true;
}

bool parseTelemetryEvent(Reader r, pb::TelemetryEvent *e)
{
    uint32_t field, wire;
    while (!r.atEnd()) {
        if (!r.tag(field, wire) || wire != kLength)
            return false;
        Reader inner{};
        if (!r.slice(inner))
            return false;
        if (field == 1) {
            if (e->has_vehicle() || !parseVehicle(inner, e->mutable_vehicle()))
                return false;
        } else if (field == 3) {
            if (!parseTelemetry(inner, e->add_telemetry()))
                return false;
        } else {
            return false;
        }
    }
    return true;
}

} // namespace

bool HciTelemetryFastPath::parse(std::string_view payload, pb::Notification *out)
{
    out->Clear();
    const auto *begin = reinterpret_cast<const uint8_t *>(payload.data());
    Reader r{begin, begin + payload.size()};
    uint32_t field, wire;
    while (!r.atEnd()) {
        if (!r.tag(field, wire))
            return false;
        if (field == 1 && wire == kVarint) {
            uint64_t n;
            if (!r.varint(n))
                return false;
            out->set_subscriptionid(int32_t(n));
        } else if (field == 2 && wire == kLength) {
            Reader event{};
            if (out->has_event() || !r.slice(event))
                return false;
            // EventWrapper: only its telemetryEvent (field 3), once.
            auto *wrapper = out->mutable_event();
            while (!event.atEnd()) {
                Reader inner{};
                if (!event.tag(field, wire) || field != 3 || wire != kLength || wrapper->has_telemetryevent()
                    || !event.slice(inner) || !parseTelemetryEvent(inner, wrapper->mutable_telemetryevent()))
                    return false;
            }
        } else {
            return false;
        }
    }
    return out->has_subscriptionid() && out->has_event();
}

} // namespace sortie::hci
