#include "MissionFiles.h"

#include "MissionLog.h"
#include "QgcPlanFormat.h"
#include "RouteValidator.h"
#include "ScanPlanCache.h"
#include "SortieFormat.h"
#include "WplFormat.h"
#include "WpmlFormat.h"

#include <QFile>

#include <algorithm>
#include <QFileInfo>
#include <QSaveFile>
#include <QCoreApplication>

namespace sortie::mission::formats {

namespace {
constexpr qint64 kMaxFileBytes = 256 * 1024 * 1024;

Result<QByteArray> readAll(const QString &path) { return readFileAtMost(path, kMaxFileBytes); }

Result<FileFormat> formatOf(const QString &path)
{
    if (const auto f = formatForPath(path))
        return *f;
    return MissionError{QCoreApplication::translate("MissionFiles", "unknown file type: use .sortie, .plan, .waypoints, .kml or .kmz"), path, 0, 0, {}};
}

Mission missionOf(Route route, const QString &path)
{
    const QString name = QFileInfo(path).completeBaseName();
    if (route.settings.name.isEmpty())
        route.settings.name = name;
    Mission m;
    m.name = name;
    m.routes.push_back(std::move(route));
    return m;
}
}

namespace {
// Every file type Sortie reads a mission from, by extension: the one list the file dialogs, the
// command line and tst_fuzzcoverage (every format has its fuzz target) go by.
struct FileType
{
    const char *extension;
    FileFormat format;
};
constexpr FileType kFileTypes[] = {
    {"sortie", FileFormat::Sortie}, {"plan", FileFormat::QgcPlan}, {"waypoints", FileFormat::Wpl},
    {"wpl", FileFormat::Wpl},       {"txt", FileFormat::Wpl},      {"kml", FileFormat::Kml},
    {"kmz", FileFormat::Wpml},
};
} // namespace

QStringList missionFileExtensions()
{
    QStringList list;
    for (const FileType &type : kFileTypes)
        list.append(QString::fromLatin1(type.extension));
    return list;
}

Result<QByteArray> readFileAtMost(const QString &path, qint64 maxBytes)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return MissionError{QCoreApplication::translate("MissionFiles", "cannot open: %1").arg(f.errorString()), path, 0, 0, {}};
    // In pieces: a pipe or a device gives what it has per read, and reports no size up front.
    QByteArray data;
    for (QByteArray piece; !(piece = f.read(std::min<qint64>(maxBytes + 1 - data.size(), 1 << 20))).isEmpty();) {
        data += piece;
        if (data.size() > maxBytes)
            return MissionError{QCoreApplication::translate("MissionFiles", "the file is larger than %1 MiB").arg(double(maxBytes) / (1024 * 1024), 0, 'g', 3),
                                path, 0, 0, {}};
    }
    if (f.error() != QFileDevice::NoError)
        return MissionError{QCoreApplication::translate("MissionFiles", "cannot open: %1").arg(f.errorString()), path, 0, 0, {}};
    return data;
}

std::optional<FileFormat> formatForPath(const QString &path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    for (const FileType &type : kFileTypes) {
        if (suffix == QLatin1String(type.extension))
            return type.format;
    }
    return std::nullopt;
}

QString formatName(FileFormat format)
{
    switch (format) {
    case FileFormat::Sortie: return QCoreApplication::translate("MissionFiles", "Sortie mission");
    case FileFormat::QgcPlan: return QCoreApplication::translate("MissionFiles", "QGroundControl plan");
    case FileFormat::Wpl: return QCoreApplication::translate("MissionFiles", "QGC WPL 110 waypoints");
    case FileFormat::Kml: return QStringLiteral("KML");
    case FileFormat::Wpml: return QCoreApplication::translate("MissionFiles", "DJI WPML");
    }
    return {};
}

Result<LoadedMission> loadMission(const QString &path)
{
    const Result<FileFormat> format = formatOf(path);
    if (!format)
        return format.error();
    const Result<QByteArray> data = readAll(path);
    if (!data)
        return data.error();
    switch (*format) {
    case FileFormat::Sortie: {
        Result<Mission> m = readSortie(*data);
        if (!m)
            return m.error().withFile(path);
        return LoadedMission{std::move(m).value(), {}};
    }
    case FileFormat::QgcPlan:
    case FileFormat::Wpl: {
        Result<ImportedRoute> r = *format == FileFormat::Wpl ? readWpl(*data) : readQgcPlan(*data);
        if (!r)
            return r.error().withFile(path);
        ImportedRoute imported = std::move(r).value();
        return LoadedMission{missionOf(std::move(imported.route), path), imported.notices};
    }
    case FileFormat::Wpml: {
        Result<WpmlImport> r = readWpml(*data);
        if (!r)
            // "route.kmz/wpmz/waylines.wpml:12:5: ...": the archive, then the document in it.
            return r.error().withFile(r.error().file.isEmpty() ? path : path + QLatin1Char('/') + r.error().file);
        WpmlImport imported = std::move(r).value();
        const QString name = QFileInfo(path).completeBaseName();
        Mission m;
        m.name = name;
        for (Route &route : imported.routes) {
            if (route.settings.name.isEmpty())
                route.settings.name = name;
            m.routes.push_back(std::move(route));
        }
        return LoadedMission{std::move(m), imported.notices};
    }
    case FileFormat::Kml:
        return MissionError{QCoreApplication::translate("MissionFiles", "a KML file holds a polygon, not a mission: import it as an area-scan boundary"), path, 0, 0, {}};
    }
    return MissionError{QStringLiteral("unreachable"), path, 0, 0, {}};
}

Result<ImportedPolygon> loadPolygon(const QString &path)
{
    const Result<QByteArray> data = readAll(path);
    if (!data)
        return data.error();
    Result<ImportedPolygon> p = readKmlPolygon(*data);
    if (!p)
        return p.error().withFile(path);
    return p;
}

Result<QStringList> saveMission(const Mission &mission, const QString &path, const SaveOptions &options)
{
    const Result<FileFormat> format = formatOf(path);
    if (!format)
        return format.error();
    ScanPlanCache cache;
    std::vector<const Route *> routes;
    if (*format == FileFormat::Sortie || (*format == FileFormat::Wpml && !options.routeIndex)) {
        for (const Route &r : mission.routes)
            routes.push_back(&r);
    } else if (options.routeIndex) {
        if (*options.routeIndex < 0 || *options.routeIndex >= int(mission.routes.size()))
            return MissionError{QCoreApplication::translate("MissionFiles", "the mission has no route %1 (it has %2)").arg(*options.routeIndex + 1).arg(mission.routes.size()), path, 0, 0, {}};
        routes.push_back(&mission.routes[size_t(*options.routeIndex)]);
    } else if (mission.routes.size() != 1) {
        return MissionError{mission.routes.empty()
                                ? QCoreApplication::translate("MissionFiles", "the mission has no route to write")
                                : QCoreApplication::translate("MissionFiles", "the mission has %1 routes and a %2 file holds one: choose the route to write (sortie-plan convert --route N), "
                                                 "or write .sortie or DJI WPML (.kmz), which hold them all")
                                      .arg(mission.routes.size()).arg(formatName(*format)),
                            path, 0, 0, {}};
    } else {
        routes.push_back(&mission.routes.front());
    }
    if (routes.empty() && *format != FileFormat::Sortie)
        return MissionError{QCoreApplication::translate("MissionFiles", "the mission has no route to write"), path, 0, 0, {}};
    for (const Route *r : routes) {
        const Result<void> gate = permitRelease(validateRoute(*r, &cache), options.override,
                                                QCoreApplication::translate("MissionFiles", "Saving route \"%1\"").arg(r->settings.name));
        if (!gate)
            return gate.error().withFile(path);
    }
    QStringList notices;
    QByteArray bytes;
    switch (*format) {
    case FileFormat::Sortie: bytes = writeSortie(mission); break;
    case FileFormat::QgcPlan: bytes = writeQgcPlan(*routes.front(), &notices, &cache); break;
    case FileFormat::Wpl: bytes = writeWpl(*routes.front(), &notices, &cache); break;
    case FileFormat::Kml: bytes = writeKmlRoute(*routes.front(), &cache); break;
    case FileFormat::Wpml: {
        const Result<WpmlExport> wpml = writeWpml(routes, options.wpml, &cache);
        if (!wpml)
            return wpml.error().withFile(path);
        bytes = wpml->kmz;
        notices = wpml->notices;
        break;
    }
    }
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size() || !f.commit())
        return MissionError{QCoreApplication::translate("MissionFiles", "cannot write: %1").arg(f.errorString()), path, 0, 0, {}};
    qCInfo(lcMission) << "saved" << path << "as" << formatName(*format);
    return notices;
}

} // namespace sortie::mission::formats
