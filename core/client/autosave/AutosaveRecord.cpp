#include "AutosaveRecord.h"

#include "JsonCursor.h"
#include "SortieFormat.h"
#include <QCoreApplication>

namespace sortie::client {

using namespace sortie::mission;
using formats::Json;

namespace {

constexpr int kFormatVersion = 1;

Result<Route> readRoute(const Json &doc, const char *key)
{
    const auto it = doc.find(key);
    if (it == doc.end() || !it->is_object()) {
        MissionError e;
        e.message = QCoreApplication::translate("AutosaveRecord", "the autosave holds no \"%1\" route").arg(QLatin1String(key));
        e.jsonPath = QStringLiteral("/%1").arg(QLatin1String(key));
        return e;
    }
    auto mission = formats::readSortie(QByteArray::fromStdString(it->dump()));
    if (!mission) {
        MissionError e = mission.error();
        e.jsonPath = QStringLiteral("/%1%2").arg(QLatin1String(key), e.jsonPath);
        e.line = e.column = 0; // lines of the re-encoded part would mislead
        return e;
    }
    if (mission->routes.size() != 1) {
        MissionError e;
        e.message = QCoreApplication::translate("AutosaveRecord", "the \"%1\" document holds %2 routes, not one").arg(QLatin1String(key)).arg(mission->routes.size());
        e.jsonPath = QStringLiteral("/%1/mission/routes").arg(QLatin1String(key));
        return e;
    }
    return mission->routes.front();
}

} // namespace

QByteArray encodeAutosaveRoute(const Route &route)
{
    Mission mission;
    mission.name = route.settings.name;
    mission.routes.push_back(route);
    return formats::writeSortie(mission);
}

QByteArray encodeAutosave(const AutosaveRecord &header, const QByteArray &working, const QByteArray &baseline)
{
    const Json head{{"format", "sortie-autosave"},
                    {"formatVersion", kFormatVersion},
                    {"savedAt", header.savedAt.toUTC().toString(Qt::ISODateWithMs).toStdString()},
                    {"server", header.server.toStdString()},
                    {"user", header.user.toStdString()},
                    {"routeId", header.routeId},
                    {"routeVersion", header.routeVersion}};
    // The routes are .sortie documents already: spliced in as they are, not parsed again.
    QByteArray out = QByteArray::fromStdString(head.dump(1));
    out.chop(2); // "\n}"
    out.reserve(out.size() + working.size() + baseline.size() + 40);
    out += ",\n \"working\": "; // i18n: not text (JSON)
    out += working.trimmed();
    out += ",\n \"baseline\": "; // i18n: not text (JSON)
    out += baseline.trimmed();
    out += "\n}\n";
    return out;
}

QByteArray encodeAutosave(const AutosaveRecord &record)
{
    return encodeAutosave(record, encodeAutosaveRoute(record.working), encodeAutosaveRoute(record.baseline));
}

Result<AutosaveRecord> decodeAutosave(const QByteArray &data)
{
    Result<Json> parsed = formats::parseJson(data);
    if (!parsed)
        return parsed.error();
    const Json &doc = parsed.value();
    auto fail = [](const QString &message, const QString &path = {}) {
        MissionError e;
        e.message = message;
        e.jsonPath = path;
        return e;
    };
    if (!doc.is_object() || doc.value("format", Json()) != "sortie-autosave")
        return fail(QCoreApplication::translate("AutosaveRecord", "not a Sortie autosave (\"format\" is not \"sortie-autosave\")"), QStringLiteral("/format"));
    const Json version = doc.value("formatVersion", Json());
    if (!version.is_number_integer() || version.get<int>() < 1 || version.get<int>() > kFormatVersion)
        return fail(QCoreApplication::translate("AutosaveRecord", "autosave format version %1 is not one this Sortie reads (1)").arg(QString::fromStdString(version.dump())),
                    QStringLiteral("/formatVersion"));
    AutosaveRecord record;
    auto text = [&doc](const char *key) {
        const Json v = doc.value(key, Json());
        return v.is_string() ? QString::fromStdString(v.get<std::string>()) : QString();
    };
    auto integer = [&doc](const char *key) {
        const Json v = doc.value(key, Json());
        return v.is_number_integer() ? v.get<int>() : -1;
    };
    record.savedAt = QDateTime::fromString(text("savedAt"), Qt::ISODateWithMs);
    if (!record.savedAt.isValid())
        return fail(QCoreApplication::translate("AutosaveRecord", "\"savedAt\" is not a date and time"), QStringLiteral("/savedAt"));
    record.server = text("server");
    record.user = text("user");
    record.routeId = integer("routeId");
    record.routeVersion = integer("routeVersion");
    auto working = readRoute(doc, "working");
    if (!working)
        return working.error();
    auto baseline = readRoute(doc, "baseline");
    if (!baseline)
        return baseline.error();
    record.working = std::move(working).value();
    record.baseline = std::move(baseline).value();
    return record;
}

} // namespace sortie::client
