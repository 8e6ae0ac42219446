#include "SbsWriter.h"

#include <cinttypes>
#include <cstdio>
#include <ctime>

namespace sortie::traffic::sbs {
namespace {

std::string number(const std::optional<double> &v, int decimals)
{
    if (!v)
        return {};
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, *v);
    return buffer;
}

std::string flag(const std::optional<bool> &v)
{
    return v ? (*v ? "-1" : "0") : "";
}

// "2026/11/26,18:44:00.000": the date and time fields of the format, UTC.
std::string dateAndTime(int64_t timeMs)
{
    const std::time_t seconds = std::time_t(timeMs / 1000);
    std::tm utc{};
    gmtime_r(&seconds, &utc);
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%04d/%02d/%02d,%02d:%02d:%02d.%03d", utc.tm_year + 1900, utc.tm_mon + 1, utc.tm_mday,
                  utc.tm_hour, utc.tm_min, utc.tm_sec, int(timeMs % 1000));
    return buffer;
}

} // namespace

std::string writeSbsLine(const SbsMessage &m, int64_t timeMs)
{
    char address[16];
    std::snprintf(address, sizeof address, "%s%06" PRIX32, m.nonIcaoAddress ? "~" : "", m.address & 0xffffffu);
    const std::string when = dateAndTime(timeMs);
    std::string line = "MSG," + std::to_string(m.transmission) + ",1,1," + address + ",1," + when + "," + when + ",";
    line += m.callsign.value_or("") + ",";
    line += number(m.altitudeFt, 0) + "," + number(m.groundSpeedKt, 0) + "," + number(m.trackDeg, 0) + ",";
    line += number(m.latitude, 5) + "," + number(m.longitude, 5) + "," + number(m.verticalRateFpm, 0) + ",";
    line += m.squawk.value_or("") + "," + flag(m.alert) + "," + flag(m.emergency) + "," + flag(m.ident) + "," + flag(m.onGround);
    return line + "\r\n";
}

} // namespace sortie::traffic::sbs
