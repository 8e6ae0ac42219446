#include "SbsReader.h"

#include <array>
#include <charconv>
#include <cmath>
#include <vector>

namespace sortie::traffic::sbs {
namespace {

constexpr size_t kFieldCount = 22;

// Field numbers as the format counts them (1-based), with the names errors use.
enum Field : size_t {
    kType = 1, kTransmission = 2, kAddress = 5, kCallsign = 11, kAltitude = 12, kGroundSpeed = 13,
    kTrack = 14, kLatitude = 15, kLongitude = 16, kVerticalRate = 17, kSquawk = 18, kAlert = 19,
    kEmergency = 20, kIdent = 21, kOnGround = 22
};

const char *nameOf(size_t field)
{
    switch (field) {
    case kTransmission: return "transmission type";
    case kAddress: return "address";
    case kCallsign: return "call sign";
    case kAltitude: return "altitude";
    case kGroundSpeed: return "ground speed";
    case kTrack: return "track";
    case kLatitude: return "latitude";
    case kLongitude: return "longitude";
    case kVerticalRate: return "vertical rate";
    case kSquawk: return "squawk";
    case kAlert: return "alert";
    case kEmergency: return "emergency";
    case kIdent: return "ident";
    case kOnGround: return "on ground";
    default: return "field";
    }
}

// What is shown of a bad value: its first 24 bytes, anything unprintable as '?'.
std::string shown(std::string_view value)
{
    std::string out;
    for (char c : value.substr(0, 24))
        out += (c >= 0x20 && c < 0x7f) ? c : '?';
    if (value.size() > 24)
        out += "...";
    return out;
}

struct LineError
{
    std::string reason;
};

std::string fieldLabel(size_t field)
{
    return "field " + std::to_string(field) + " (" + nameOf(field) + ")";
}

std::optional<double> number(std::string_view value, size_t field, double min, double max)
{
    if (value.empty())
        return std::nullopt;
    double v = 0;
    const char *end = value.data() + value.size();
    const auto [ptr, ec] = std::from_chars(value.data(), end, v, std::chars_format::fixed);
    if (ec != std::errc() || ptr != end || !std::isfinite(v))
        throw LineError{fieldLabel(field) + ": '" + shown(value) + "' is not a number"};
    if (v < min || v > max) {
        throw LineError{fieldLabel(field) + ": " + shown(value) + " is out of " + std::to_string(int64_t(min)) + ".."
                        + std::to_string(int64_t(max))};
    }
    return v;
}

std::optional<bool> flag(std::string_view value, size_t field)
{
    if (value.empty())
        return std::nullopt;
    if (value == "-1" || value == "1")
        return true;
    if (value == "0")
        return false;
    throw LineError{fieldLabel(field) + ": '" + shown(value) + "' is not -1, 1 or 0"};
}

uint32_t address(std::string_view value, bool *nonIcao)
{
    *nonIcao = !value.empty() && value.front() == '~';
    if (*nonIcao)
        value.remove_prefix(1);
    uint32_t v = 0;
    const char *end = value.data() + value.size();
    const auto [ptr, ec] = std::from_chars(value.data(), end, v, 16);
    if (value.empty() || value.size() > 6 || ec != std::errc() || ptr != end)
        throw LineError{fieldLabel(kAddress) + ": '" + shown(value) + "' is not a 24-bit hexadecimal address"};
    return v;
}

std::optional<std::string> callsign(std::string_view value)
{
    while (!value.empty() && value.back() == ' ')
        value.remove_suffix(1);
    if (value.empty())
        return std::nullopt;
    if (value.size() > 8)
        throw LineError{fieldLabel(kCallsign) + ": '" + shown(value) + "' is longer than 8 characters"};
    for (char c : value) {
        const bool ok = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == ' ' || c == '-';
        if (!ok)
            throw LineError{fieldLabel(kCallsign) + ": '" + shown(value) + "' holds a character a call sign cannot"};
    }
    return std::string(value);
}

std::optional<std::string> squawk(std::string_view value)
{
    if (value.empty())
        return std::nullopt;
    bool octal = value.size() == 4;
    for (char c : value)
        octal = octal && c >= '0' && c <= '7';
    if (!octal)
        throw LineError{fieldLabel(kSquawk) + ": '" + shown(value) + "' is not four octal digits"};
    return std::string(value);
}

bool knownOtherType(std::string_view type)
{
    return type == "SEL" || type == "ID" || type == "AIR" || type == "STA" || type == "CLK";
}

} // namespace

SbsReader::SbsReader(size_t maxLineLength)
    : m_maxLineLength(maxLineLength)
{
}

std::optional<SbsReader::Result> SbsReader::readLine(std::string_view line, uint64_t lineNumber, bool *skipped)
{
    if (skipped)
        *skipped = false;
    if (!line.empty() && line.back() == '\r')
        line.remove_suffix(1);
    std::array<std::string_view, kFieldCount + 1> fields{}; // fields[1..22]
    size_t count = 0;
    for (size_t start = 0;;) {
        const size_t comma = line.find(',', start);
        const std::string_view field = line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
        if (++count <= kFieldCount)
            fields[count] = field;
        if (comma == std::string_view::npos)
            break;
        start = comma + 1;
    }
    if (line.empty() || (fields[kType] != "MSG" && knownOtherType(fields[kType]))) {
        if (skipped)
            *skipped = true;
        return std::nullopt;
    }
    const auto fail = [lineNumber](std::string reason) { return Result{SbsError{lineNumber, std::move(reason)}}; };
    if (fields[kType] != "MSG")
        return fail("field 1 (message type): '" + shown(fields[kType]) + "' is not MSG, SEL, ID, AIR, STA or CLK");
    if (count != kFieldCount)
        return fail(std::to_string(count) + " fields where an SBS-1 line has 22");
    try {
        SbsMessage m;
        m.line = lineNumber;
        const std::string_view t = fields[kTransmission];
        if (t.size() != 1 || t[0] < '1' || t[0] > '8')
            throw LineError{fieldLabel(kTransmission) + ": '" + shown(t) + "' is not 1 to 8"};
        m.transmission = t[0] - '0';
        m.address = address(fields[kAddress], &m.nonIcaoAddress);
        m.callsign = callsign(fields[kCallsign]);
        m.altitudeFt = number(fields[kAltitude], kAltitude, -2000, 130000);
        m.groundSpeedKt = number(fields[kGroundSpeed], kGroundSpeed, 0, 4000);
        m.trackDeg = number(fields[kTrack], kTrack, 0, 360);
        m.latitude = number(fields[kLatitude], kLatitude, -90, 90);
        m.longitude = number(fields[kLongitude], kLongitude, -180, 180);
        m.verticalRateFpm = number(fields[kVerticalRate], kVerticalRate, -100000, 100000);
        m.squawk = squawk(fields[kSquawk]);
        m.alert = flag(fields[kAlert], kAlert);
        m.emergency = flag(fields[kEmergency], kEmergency);
        m.ident = flag(fields[kIdent], kIdent);
        m.onGround = flag(fields[kOnGround], kOnGround);
        if (m.latitude.has_value() != m.longitude.has_value())
            throw LineError{m.latitude ? std::string("a latitude without a longitude") : std::string("a longitude without a latitude")};
        return Result{std::move(m)};
    } catch (const LineError &e) {
        return fail(e.reason);
    }
}

void SbsReader::push(std::string_view bytes)
{
    while (!bytes.empty()) {
        const size_t newline = bytes.find('\n');
        const std::string_view piece = bytes.substr(0, newline);
        if (!m_discarding) {
            if (m_partial.size() + piece.size() > m_maxLineLength) {
                m_ready.push_back(SbsError{m_line + 1, "longer than " + std::to_string(m_maxLineLength) + " bytes: skipped to the next newline"});
                m_partial.clear();
                m_discarding = true;
            } else {
                m_partial.append(piece);
            }
        }
        if (newline == std::string_view::npos)
            return;
        bytes.remove_prefix(newline + 1);
        finishLine();
    }
}

void SbsReader::finishLine()
{
    ++m_line;
    if (m_discarding) {
        m_discarding = false;
        return;
    }
    bool skipped = false;
    if (auto result = readLine(m_partial, m_line, &skipped))
        m_ready.push_back(std::move(*result));
    m_skipped += skipped ? 1 : 0;
    m_partial.clear();
}

std::optional<SbsReader::Result> SbsReader::next()
{
    if (m_ready.empty())
        return std::nullopt;
    Result r = std::move(m_ready.front());
    m_ready.pop_front();
    return r;
}

} // namespace sortie::traffic::sbs
