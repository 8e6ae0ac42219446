#include "HciDecodedSize.h"

#include <google/protobuf/descriptor.h>
#include <google/protobuf/message.h>

#include <cstdint>
#include <limits>
#include <string>
#include <unordered_map>

namespace sortie::hci {
namespace {

namespace pb = google::protobuf;

constexpr int kMaxDepth = 100;                   // protobuf's default recursion limit
constexpr size_t kScalar = 8;                    // a repeated scalar element, at most
constexpr size_t kPointer = sizeof(void *);      // a repeated message's slot
constexpr size_t kStringObject = sizeof(std::string);
constexpr size_t kUnknownField = 16;             // one entry of an UnknownFieldSet
constexpr size_t kFallbackObject = 64;

enum WireType : uint32_t { Varint = 0, Fixed64 = 1, Delimited = 2, StartGroup = 3, EndGroup = 4, Fixed32 = 5 };

bool readVarint(const char *&p, const char *end, uint64_t &value)
{
    value = 0;
    for (int shift = 0; shift < 64; shift += 7) {
        if (p == end)
            return false;
        const auto byte = uint8_t(*p++);
        value |= uint64_t(byte & 0x7f) << shift;
        if (!(byte & 0x80))
            return true;
    }
    return false;
}

// The wire type protobuf writes a field of this type with (packed repeated scalars also arrive as
// Delimited). A field arriving with another wire type is kept as an unknown field.
WireType wireTypeOf(const pb::FieldDescriptor &field)
{
    switch (field.type()) {
    case pb::FieldDescriptor::TYPE_DOUBLE:
    case pb::FieldDescriptor::TYPE_FIXED64:
    case pb::FieldDescriptor::TYPE_SFIXED64:
        return Fixed64;
    case pb::FieldDescriptor::TYPE_FLOAT:
    case pb::FieldDescriptor::TYPE_FIXED32:
    case pb::FieldDescriptor::TYPE_SFIXED32:
        return Fixed32;
    case pb::FieldDescriptor::TYPE_STRING:
    case pb::FieldDescriptor::TYPE_BYTES:
    case pb::FieldDescriptor::TYPE_MESSAGE:
        return Delimited;
    case pb::FieldDescriptor::TYPE_GROUP:
        return StartGroup;
    default:
        return Varint;
    }
}

class Estimate
{
public:
    explicit Estimate(size_t limit)
        : m_limit(limit)
    {
    }
    size_t bytes() const { return m_bytes; }
    bool over() const { return m_bytes > m_limit; }

    // Walks the fields of one message of `type` (nullptr: a group no descriptor names) from `p` to
    // `end`; for a group, up to its end tag. False when the bytes are malformed.
    bool message(const char *&p, const char *end, const pb::Descriptor *type, int depth, uint32_t groupNumber)
    {
        while (p != end) {
            // A tag is at most five bytes, of which protobuf keeps the low 32 bits (as it does here).
            const char *tagStart = p;
            uint64_t wideTag = 0;
            if (!readVarint(p, end, wideTag) || p - tagStart > 5)
                return false;
            const auto tag = uint32_t(wideTag);
            const uint32_t number = tag >> 3;
            if (number == 0)
                return false;
            const auto wire = WireType(tag & 7);
            if (wire == EndGroup)
                return number == groupNumber;
            const pb::FieldDescriptor *field = type ? type->FindFieldByNumber(int(number)) : nullptr;
            const bool known = field && (wireTypeOf(*field) == wire || (wire == Delimited && field->is_packable()));
            // Unknown enum values are kept as unknown fields too, so an enum is counted as one.
            const bool enumField = known && field->type() == pb::FieldDescriptor::TYPE_ENUM;
            switch (wire) {
            case Varint: {
                uint64_t value = 0;
                if (!readVarint(p, end, value))
                    return false;
                add(!known || enumField ? kUnknownField : field->is_repeated() ? kScalar : 0);
                break;
            }
            case Fixed64:
            case Fixed32: {
                const size_t width = wire == Fixed64 ? 8 : 4;
                if (size_t(end - p) < width)
                    return false;
                p += width;
                add(!known ? kUnknownField : field->is_repeated() ? kScalar : 0);
                break;
            }
            case Delimited: {
                uint64_t length = 0;
                if (!readVarint(p, end, length) || length > uint64_t(end - p))
                    return false;
                const char *inner = p;
                p += length;
                if (known && field->type() == pb::FieldDescriptor::TYPE_MESSAGE) {
                    if (depth + 1 > kMaxDepth)
                        return false;
                    add(objectSize(field->message_type()) + (field->is_repeated() ? kPointer : 0));
                    if (!message(inner, p, field->message_type(), depth + 1, 0))
                        return false;
                } else if (known && (field->type() == pb::FieldDescriptor::TYPE_STRING
                                     || field->type() == pb::FieldDescriptor::TYPE_BYTES)) {
                    add(size_t(length) + kStringObject);
                } else if (known) {
                    add(size_t(length) * kScalar); // packed: at most one element a byte
                } else {
                    add(size_t(length) + kStringObject + kUnknownField);
                }
                break;
            }
            case StartGroup: {
                if (depth + 1 > kMaxDepth)
                    return false;
                const pb::Descriptor *groupType = known ? field->message_type() : nullptr;
                add(groupType ? objectSize(groupType) + (field->is_repeated() ? kPointer : 0) : kUnknownField);
                if (!message(p, end, groupType, depth + 1, number))
                    return false;
                break;
            }
            default:
                return false;
            }
            if (over())
                return true; // enough is known: the callers stop too
        }
        return groupNumber == 0; // a group must close with its end tag
    }

private:
    void add(size_t n) { m_bytes = n > std::numeric_limits<size_t>::max() - m_bytes ? std::numeric_limits<size_t>::max() : m_bytes + n; }

    size_t objectSize(const pb::Descriptor *type)
    {
        auto [it, inserted] = m_objectSizes.try_emplace(type, kFallbackObject);
        if (inserted) {
            if (const pb::Message *prototype = pb::MessageFactory::generated_factory()->GetPrototype(type))
                it->second = prototype->SpaceUsedLong();
        }
        return it->second;
    }

    size_t m_limit;
    size_t m_bytes = 0;
    std::unordered_map<const pb::Descriptor *, size_t> m_objectSizes;
};

} // namespace

std::optional<size_t> estimateDecodedBytes(std::string_view wire, const google::protobuf::Descriptor &type, size_t limit)
{
    Estimate estimate(limit);
    const char *p = wire.data();
    if (!estimate.message(p, wire.data() + wire.size(), &type, 0, 0))
        return std::nullopt;
    return estimate.bytes();
}

} // namespace sortie::hci
