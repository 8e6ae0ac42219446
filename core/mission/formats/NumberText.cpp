#include "NumberText.h"

#include <charconv>
#include <cmath>

namespace sortie::mission::formats {

QByteArray shortestNumber(double v)
{
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return QByteArray(buf, int(r.ptr - buf));
}

std::optional<double> parseNumber(QByteArrayView text)
{
    const char *begin = text.data(), *end = text.data() + text.size();
    if (begin != end && *begin == '+')
        ++begin;
    double v = 0;
    const auto r = std::from_chars(begin, end, v);
    if (r.ec != std::errc() || r.ptr != end || !std::isfinite(v))
        return std::nullopt;
    return v;
}

} // namespace sortie::mission::formats
