#include "WplFormat.h"

#include <cmath>

#include "NumberText.h"

#include <QList>
#include <QCoreApplication>

namespace sortie::mission::formats {

namespace {
const char *const kFieldNames[] = {"index", "current", "frame", "command", "param1", "param2", "param3", "param4",
                                   "latitude", "longitude", "altitude", "autocontinue"};

MissionError lineError(int line, const QString &message)
{
    return MissionError{message, {}, line, 0, {}};
}

QList<QByteArrayView> fields(QByteArrayView line)
{
    QList<QByteArrayView> out;
    qsizetype i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == '\t' || line[i] == ' '))
            ++i;
        const qsizetype start = i;
        while (i < line.size() && line[i] != '\t' && line[i] != ' ')
            ++i;
        if (i > start)
            out << line.sliced(start, i - start);
    }
    return out;
}
}

Result<WplItems> readWplItems(const QByteArray &input)
{
    QByteArrayView data(input);
    if (data.startsWith("\xEF\xBB\xBF"))
        data = data.sliced(3);
    std::vector<MavlinkItem> items;
    std::optional<HomePosition> home;
    int lineNo = 0;
    int expectedIndex = 0;
    bool headerSeen = false;
    qsizetype pos = 0;
    while (pos <= data.size()) {
        qsizetype end = data.indexOf('\n', pos);
        if (end < 0)
            end = data.size();
        QByteArrayView line = data.sliced(pos, end - pos);
        pos = end + 1;
        ++lineNo;
        if (line.endsWith('\r'))
            line.chop(1);
        if (!headerSeen) {
            const QByteArray header = line.toByteArray().trimmed();
            if (!header.startsWith("QGC WPL"))
                return lineError(lineNo, QCoreApplication::translate("WplFormat", "not a waypoint file: expected \"QGC WPL 110\", found \"%1\"")
                                             .arg(QString::fromUtf8(header.left(40))));
            if (header != "QGC WPL 110")
                return lineError(lineNo, QCoreApplication::translate("WplFormat", "unsupported waypoint file version \"%1\"; Sortie reads QGC WPL 110")
                                             .arg(QString::fromUtf8(header)));
            headerSeen = true;
            continue;
        }
        const QList<QByteArrayView> f = fields(line);
        if (f.isEmpty())
            continue;
        if (f.size() != 12)
            return lineError(lineNo, QCoreApplication::translate("WplFormat", "expected 12 tab-separated fields, found %1").arg(f.size()));
        double v[12];
        for (int i = 0; i < 12; ++i) {
            const auto n = parseNumber(f[i]);
            if (!n)
                return lineError(lineNo, QCoreApplication::translate("WplFormat", "field %1 (%2) is not a number: \"%3\"")
                                             .arg(i + 1).arg(QLatin1String(kFieldNames[i])).arg(QString::fromUtf8(f[i].toByteArray().left(40))));
            v[i] = *n;
        }
        for (int i : {0, 1, 2, 3, 11})
            // Range first: converting a double beyond int's range to int is undefined (a fuzz finding).
            if (!(v[i] >= 0 && v[i] <= 2147483647.0) || v[i] != std::floor(v[i]))
                return lineError(lineNo, QCoreApplication::translate("WplFormat", "field %1 (%2) must be a whole number, found %3")
                                             .arg(i + 1).arg(QLatin1String(kFieldNames[i])).arg(v[i]));
        if (int(v[0]) != expectedIndex)
            return lineError(lineNo, QCoreApplication::translate("WplFormat", "item %1 where item %2 was expected").arg(int(v[0])).arg(expectedIndex));
        ++expectedIndex;
        if (expectedIndex == 1) {
            const GeoPoint g{v[8], v[9]};
            if (!g.isValid())
                return lineError(lineNo, QCoreApplication::translate("WplFormat", "the home position %1, %2 is not a position").arg(v[8]).arg(v[9]));
            home = HomePosition{g, v[10]};
            continue;
        }
        MavlinkItem item;
        item.frame = int(v[2]);
        item.command = int(v[3]);
        for (int i = 0; i < 4; ++i)
            item.param[i] = v[4 + i];
        item.latitude = v[8];
        item.longitude = v[9];
        item.altitude = v[10];
        item.autoContinue = v[11] != 0;
        item.line = lineNo;
        items.push_back(item);
        if (pos > data.size())
            break;
    }
    if (!headerSeen)
        return lineError(1, QCoreApplication::translate("WplFormat", "the file is empty"));
    if (expectedIndex == 0)
        return lineError(lineNo, QCoreApplication::translate("WplFormat", "the file has no items, not even the home position"));
    return WplItems{home, std::move(items)};
}

Result<ImportedRoute> readWpl(const QByteArray &input)
{
    const Result<WplItems> read = readWplItems(input);
    if (!read)
        return read.error();
    return routeFromMavlink(read.value().items, read.value().home, kWplDefaultSpeed);
}

QByteArray writeWpl(const Route &route, QStringList *notices, ScanPlanCache *cache)
{
    MavlinkExport out = routeToMavlink(route, kWplDefaultSpeed, cache);
    HomePosition home;
    if (route.settings.home) {
        home = *route.settings.home;
    } else {
        if (!route.segments.empty())
            home.position = anchorOf(route.segments.front());
        out.notices.prepend(QCoreApplication::translate("WplFormat", "The route has no home position: the first point was written as home, at 0 m AMSL."));
    }
    QByteArray text = "QGC WPL 110\n"; // i18n: not text (the file format's header)
    auto line = [&](int index, int current, int frame, int command, const double p[4], double lat, double lon, double alt, bool autoContinue) {
        text += QByteArray::number(index) + '\t' + QByteArray::number(current) + '\t' + QByteArray::number(frame) + '\t'
              + QByteArray::number(command);
        for (int i = 0; i < 4; ++i)
            text += '\t' + shortestNumber(p[i]);
        text += '\t' + shortestNumber(lat) + '\t' + shortestNumber(lon) + '\t' + shortestNumber(alt) + '\t'
              + (autoContinue ? "1" : "0") + '\n';
    };
    const double zero[4] = {0, 0, 0, 0};
    line(0, 1, mav::Global, mav::NavWaypoint, zero, home.position.latitude, home.position.longitude, home.altitudeAmsl, true);
    int index = 1;
    for (const MavlinkItem &i : out.items)
        line(index++, 0, i.frame, i.command, i.param, i.latitude, i.longitude, i.altitude, i.autoContinue);
    if (notices)
        *notices << out.notices;
    return text;
}

} // namespace sortie::mission::formats
