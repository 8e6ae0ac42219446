#include "TelemetryBlockCodec.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace sortie::flightlog {

using vehicle::TelemetryField;
using vehicle::TelemetrySample;

namespace {

// Version 2 added kConstant; version 1 blocks (logs written before) read as they always did.
constexpr uint8_t kVersion = 2;
constexpr uint8_t kSecondOrder = 1; // values stored as second differences
constexpr uint8_t kHasMissing = 2;  // a bitmap of missing (NaN) values follows the times
constexpr uint8_t kSameTimes = 4;   // no times: the same as the last field that had its own
// Every value the same (a fix type, a mode, a parked vehicle): the value once. A quarter of what a
// sensor reports at 10 Hz is such a field, and at a byte a zero difference it cost a byte a value.
constexpr uint8_t kConstant = 8;
// The most samples a constant field holds in a block: its payload no longer bounds its count, so
// this does (a block is about a second; 16,384 is 1.6 kHz).
constexpr uint64_t kMaxConstantRun = 16384;
constexpr double kMaxQuantum = 9007199254740992.0; // 2^53: beyond it a value is not representable

uint64_t zigzag(int64_t v) { return (uint64_t(v) << 1) ^ uint64_t(v >> 63); }
int64_t unzigzag(uint64_t v) { return int64_t(v >> 1) ^ -int64_t(v & 1); }

void putVarint(std::string &out, uint64_t v)
{
    while (v >= 0x80) {
        out.push_back(char(uint8_t(v) | 0x80));
        v >>= 7;
    }
    out.push_back(char(v));
}

size_t varintSize(uint64_t v)
{
    size_t n = 1;
    while (v >= 0x80) {
        v >>= 7;
        ++n;
    }
    return n;
}

// Differences taken in unsigned arithmetic: defined for any input, exact for the ranges we store.
int64_t minus(int64_t a, int64_t b) { return int64_t(uint64_t(a) - uint64_t(b)); }
int64_t plus(int64_t a, int64_t b) { return int64_t(uint64_t(a) + uint64_t(b)); }

class Reader
{
public:
    explicit Reader(std::string_view data) : m_p(data.data()), m_end(data.data() + data.size()) {}
    bool varint(uint64_t *v)
    {
        uint64_t result = 0;
        for (int shift = 0; shift < 64; shift += 7) {
            if (m_p == m_end)
                return false;
            const uint8_t b = uint8_t(*m_p++);
            result |= uint64_t(b & 0x7f) << shift;
            if (!(b & 0x80)) {
                *v = result;
                return true;
            }
        }
        return false;
    }
    bool svarint(int64_t *v)
    {
        uint64_t u;
        if (!varint(&u))
            return false;
        *v = unzigzag(u);
        return true;
    }
    bool byte(uint8_t *b)
    {
        if (m_p == m_end)
            return false;
        *b = uint8_t(*m_p++);
        return true;
    }
    bool bytes(size_t n, std::string_view *out)
    {
        if (size_t(m_end - m_p) < n)
            return false;
        *out = std::string_view(m_p, n);
        m_p += n;
        return true;
    }
    size_t left() const { return size_t(m_end - m_p); }

private:
    const char *m_p;
    const char *m_end;
};

bool fail(std::string *error, const char *why)
{
    if (error)
        *error = why;
    return false;
}

struct Header
{
    int64_t t0 = 0, t1 = 0;
    uint64_t fieldCount = 0;
    uint8_t version = kVersion;
};

// Checks the CRC and reads the header; `body` is left at the first field.
bool openBlock(std::string_view block, Header *h, Reader *body, std::string *error)
{
    if (block.size() < 1 + 3 + 4)
        return fail(error, "block too short");
    uint32_t stored;
    std::memcpy(&stored, block.data() + block.size() - 4, 4);
    const std::string_view content = block.substr(0, block.size() - 4);
    if (crc32(content) != stored) // little-endian machines only: we write it the same way
        return fail(error, "checksum mismatch");
    Reader r(content);
    uint8_t version;
    int64_t span;
    if (!r.byte(&version) || version < 1 || version > kVersion)
        return fail(error, "unknown block version");
    if (!r.svarint(&h->t0) || !r.svarint(&span) || span < 0 || !r.varint(&h->fieldCount)
        || h->fieldCount > vehicle::kTelemetryFieldCount)
        return fail(error, "bad block header");
    h->t1 = plus(h->t0, span);
    h->version = version;
    *body = r;
    return true;
}

struct FieldHeader
{
    TelemetryField field;
    uint64_t count;
    uint8_t flags;
    std::string_view payload;
};

// `seen` marks the fields read so far: a field twice in one block is damage (the encoder writes each
// once), and would make a field's samples two runs that each reader joins differently.
bool readFieldHeader(Reader &r, uint8_t version, FieldHeader *f, uint32_t *seen, std::string *error)
{
    uint8_t id, flags;
    uint64_t count, length;
    if (!r.byte(&id) || id >= vehicle::kTelemetryFieldCount || !r.varint(&count) || !r.byte(&flags)
        || !r.varint(&length) || length > r.left() || count == 0 || length == 0)
        return fail(error, "bad field header");
    const bool constant = version >= 2 && (flags & kConstant);
    if (constant ? count > kMaxConstantRun || (flags & kHasMissing) : count > length * 8)
        return fail(error, "bad field header");
    if (*seen & (1u << id))
        return fail(error, "a field twice in one block");
    *seen |= 1u << id;
    f->field = TelemetryField(id);
    f->count = count;
    f->flags = constant || version >= 2 ? flags : uint8_t(flags & ~kConstant);
    r.bytes(size_t(length), &f->payload);
    return true;
}

// Reads the field's times (into `times`, unless it shares the last field's) and leaves `r` at what follows.
bool readTimes(const FieldHeader &f, int64_t t0, Reader &r, std::vector<int64_t> &times, std::string *error)
{
    if (f.flags & kSameTimes) {
        if (times.size() != f.count)
            return fail(error, "shared times of another length");
        return true;
    }
    times.resize(size_t(f.count));
    int64_t t = t0, d = 0;
    for (size_t i = 0; i < f.count; ++i) {
        int64_t v;
        if (!r.svarint(&v))
            return fail(error, "times cut short");
        if (i == 0) {
            t = plus(t0, v);
        } else {
            d = plus(d, v);
            t = plus(t, d);
        }
        times[i] = t;
    }
    return true;
}

bool decodeValues(const FieldHeader &f, Reader &r, const std::vector<int64_t> &times, FieldSamples *out, std::string *error)
{
    out->field = f.field;
    out->samples.resize(size_t(f.count));
    for (size_t i = 0; i < f.count; ++i)
        out->samples[i].time = times[i];
    std::string_view missing;
    if ((f.flags & kHasMissing) && !r.bytes(size_t((f.count + 7) / 8), &missing))
        return fail(error, "missing-value map cut short");
    const double step = fieldStep(f.field);
    int64_t q = 0, dq = 0;
    size_t present = 0;
    for (size_t i = 0; i < f.count; ++i) {
        if (!missing.empty() && (uint8_t(missing[i / 8]) >> (i % 8)) & 1) {
            out->samples[i].value = std::nan("");
            continue;
        }
        if (present > 0 && (f.flags & kConstant)) { // the value once, for every sample
            out->samples[i].value = double(q) * step;
            continue;
        }
        int64_t v;
        if (!r.svarint(&v))
            return fail(error, "values cut short");
        if (present == 0) {
            q = v;
        } else if (present == 1 || !(f.flags & kSecondOrder)) {
            dq = v;
            q = plus(q, dq);
        } else {
            dq = plus(dq, v);
            q = plus(q, dq);
        }
        ++present;
        out->samples[i].value = double(q) * step;
    }
    if (r.left())
        return fail(error, "trailing bytes in a field");
    return true;
}

bool sameTimes(const FieldSamples &a, const FieldSamples &b)
{
    if (a.samples.size() != b.samples.size())
        return false;
    for (size_t i = 0; i < a.samples.size(); ++i) {
        if (a.samples[i].time != b.samples[i].time)
            return false;
    }
    return true;
}

// `timesOf`: the last field written with its own times; this one shares them when they are equal
// (a telemetry message gives all its fields one time).
void encodeField(const FieldSamples &f, int64_t t0, const FieldSamples *&timesOf, std::string &out)
{
    const size_t n = f.samples.size();
    std::string payload;
    payload.reserve(n * 3);
    const bool shared = timesOf && sameTimes(f, *timesOf);
    if (!shared)
        timesOf = &f;
    int64_t prevT = t0, prevD = 0;
    for (size_t i = 0; i < n && !shared; ++i) {
        const int64_t t = f.samples[i].time;
        if (i == 0) {
            putVarint(payload, zigzag(minus(t, t0)));
        } else {
            const int64_t d = minus(t, prevT);
            putVarint(payload, zigzag(minus(d, prevD)));
            prevD = d;
        }
        prevT = t;
    }
    const double step = fieldStep(f.field);
    std::vector<int64_t> q;
    q.reserve(n);
    std::string missing;
    for (size_t i = 0; i < n; ++i) {
        const double scaled = std::round(f.samples[i].value / step);
        if (!std::isfinite(scaled) || std::fabs(scaled) > kMaxQuantum) {
            if (missing.empty())
                missing.assign((n + 7) / 8, '\0');
            missing[i / 8] = char(uint8_t(missing[i / 8]) | (1u << (i % 8)));
            continue;
        }
        q.push_back(int64_t(scaled));
    }
    // First or second differences: whichever is shorter for this field in this block.
    size_t first = 0, second = 0;
    for (size_t j = 1; j < q.size(); ++j) {
        first += varintSize(zigzag(q[j] - q[j - 1]));
        second += varintSize(zigzag(j == 1 ? q[1] - q[0] : (q[j] - q[j - 1]) - (q[j - 1] - q[j - 2])));
    }
    const bool constant = missing.empty() && n <= kMaxConstantRun && std::all_of(q.begin(), q.end(), [&](int64_t v) { return v == q[0]; });
    const bool secondOrder = !constant && second < first;
    uint8_t flags = secondOrder ? kSecondOrder : 0;
    if (constant)
        flags |= kConstant;
    if (shared)
        flags |= kSameTimes;
    if (!missing.empty()) {
        flags |= kHasMissing;
        payload += missing;
    }
    for (size_t j = 0; j < (constant ? 1 : q.size()); ++j) {
        int64_t v;
        if (j == 0)
            v = q[0];
        else if (j == 1 || !secondOrder)
            v = q[j] - q[j - 1];
        else
            v = (q[j] - q[j - 1]) - (q[j - 1] - q[j - 2]);
        putVarint(payload, zigzag(v));
    }
    out.push_back(char(uint8_t(f.field)));
    putVarint(out, n);
    out.push_back(char(flags));
    putVarint(out, payload.size());
    out += payload;
}

} // namespace

double fieldStep(TelemetryField field)
{
    // Angles are degrees in the store but the log's quanta stay in radians, what the protocols send:
    // the integers on disk mean what they meant before the store spoke degrees, so every log reads
    // the same. 1e-9 rad is 5.7e-8 degrees.
    switch (field) {
    case TelemetryField::Latitude:
    case TelemetryField::Longitude:
    case TelemetryField::HomeLatitude:
    case TelemetryField::HomeLongitude:
        return vehicle::degreesFromRadians(1e-9); // 6 mm on the ground
    case TelemetryField::AltitudeAmsl:
    case TelemetryField::AltitudeAgl:
    case TelemetryField::HomeAltitudeAmsl:
        return 1e-3; // m
    case TelemetryField::Roll:
    case TelemetryField::Pitch:
    case TelemetryField::Heading:
    case TelemetryField::Course:
        return vehicle::degreesFromRadians(1e-5); // 0.0006 degrees
    case TelemetryField::GroundSpeed:
    case TelemetryField::AirSpeed:
    case TelemetryField::VerticalSpeed:
    case TelemetryField::BatteryVoltage:
    case TelemetryField::BatteryCurrent:
        return 1e-3; // m/s, V, A
    case TelemetryField::BatteryRemaining:
        return 1e-4; // 0.01 %
    case TelemetryField::Hdop:
        return 1e-2;
    default:
        return 1; // counts, enumerations, booleans
    }
}

double quantize(TelemetryField field, double value)
{
    const double step = fieldStep(field);
    const double scaled = std::round(value / step);
    if (!std::isfinite(scaled) || std::fabs(scaled) > kMaxQuantum)
        return std::nan("");
    return double(int64_t(scaled)) * step;
}

std::string TelemetryBlockCodec::encode(const BlockFields &fields)
{
    int64_t t0 = INT64_MAX, t1 = INT64_MIN;
    size_t used = 0, values = 0;
    for (const FieldSamples &f : fields) {
        if (f.samples.empty())
            continue;
        ++used;
        values += f.samples.size();
        for (const TelemetrySample &sample : f.samples) {
            t0 = std::min(t0, sample.time);
            t1 = std::max(t1, sample.time);
        }
    }
    std::string out;
    out.reserve(16 + values * 3);
    out.push_back(char(kVersion));
    if (!used)
        t0 = t1 = 0;
    putVarint(out, zigzag(t0));
    putVarint(out, zigzag(minus(t1, t0)));
    putVarint(out, used);
    const FieldSamples *timesOf = nullptr;
    for (const FieldSamples &f : fields) {
        if (!f.samples.empty())
            encodeField(f, t0, timesOf, out);
    }
    const uint32_t crc = crc32(out);
    out.append(reinterpret_cast<const char *>(&crc), 4);
    return out;
}

std::optional<BlockSummary> TelemetryBlockCodec::summarize(std::string_view block, std::string *error)
{
    Header h;
    Reader r(block);
    if (!openBlock(block, &h, &r, error))
        return std::nullopt;
    BlockSummary s;
    s.t0 = h.t0;
    s.t1 = h.t1;
    uint64_t timesCount = 0;
    uint32_t seen = 0;
    for (uint64_t i = 0; i < h.fieldCount; ++i) {
        FieldHeader f;
        if (!readFieldHeader(r, h.version, &f, &seen, error))
            return std::nullopt;
        if ((f.flags & kSameTimes) && (i == 0 || f.count != timesCount)) {
            fail(error, "shared times of another length");
            return std::nullopt;
        }
        if (!(f.flags & kSameTimes))
            timesCount = f.count;
        s.counts[size_t(f.field)] += uint32_t(f.count);
        s.total += uint32_t(f.count);
    }
    return s;
}

std::optional<BlockFields> TelemetryBlockCodec::decode(std::string_view block, std::string *error,
                                                       std::optional<TelemetryField> only)
{
    Header h;
    Reader r(block);
    if (!openBlock(block, &h, &r, error))
        return std::nullopt;
    BlockFields fields;
    fields.reserve(only ? 1 : size_t(h.fieldCount));
    std::vector<int64_t> times;
    uint32_t seen = 0;
    for (uint64_t i = 0; i < h.fieldCount; ++i) {
        FieldHeader f;
        if (!readFieldHeader(r, h.version, &f, &seen, error))
            return std::nullopt;
        Reader payload(f.payload);
        // Times are read for every field: a later one may share them.
        if (!readTimes(f, h.t0, payload, times, error))
            return std::nullopt;
        if (only && f.field != *only)
            continue;
        FieldSamples out;
        if (!decodeValues(f, payload, times, &out, error))
            return std::nullopt;
        fields.push_back(std::move(out));
    }
    return fields;
}

uint32_t crc32(std::string_view data)
{
    static const auto table = [] {
        std::array<uint32_t, 256> t{};
        for (uint32_t i = 0; i < 256; ++i) {
            uint32_t c = i;
            for (int k = 0; k < 8; ++k)
                c = c & 1 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
            t[i] = c;
        }
        return t;
    }();
    uint32_t c = 0xFFFFFFFFu;
    for (const char ch : data)
        c = table[(c ^ uint8_t(ch)) & 0xFF] ^ (c >> 8);
    return c ^ 0xFFFFFFFFu;
}

} // namespace sortie::flightlog
