#include "FlightLogExport.h"

#include <QDateTime>
#include <QFileDevice>
#include <QTextStream>
#include <QXmlStreamWriter>

#include <cmath>
#include <numbers>
#include <QCoreApplication>

namespace sortie::flightlog {

using vehicle::TelemetryField;

namespace {

QString utc(int64_t ms)
{
    return QDateTime::fromMSecsSinceEpoch(ms, Qt::UTC).toString(Qt::ISODateWithMs);
}

// One time of one vehicle: the value of each field sent at that time (NaN for the others).
struct Row
{
    int64_t time = 0;
    std::array<double, vehicle::kTelemetryFieldCount> values;
};

template<typename Visit>
void forEachRow(const FlightLog &log, int vehicle, Visit visit)
{
    const FlightLog::Vehicle &v = log.vehicles()[size_t(vehicle)];
    const vehicle::TelemetryBatch updates = log.updatesBetween(vehicle, v.start - 1, v.end);
    Row row;
    row.values.fill(std::nan(""));
    bool open = false;
    for (const vehicle::TelemetryUpdate &u : updates) {
        if (open && u.time != row.time) {
            visit(row);
            row.values.fill(std::nan(""));
        }
        row.time = u.time;
        row.values[size_t(u.field)] = u.value;
        open = true;
    }
    if (open)
        visit(row);
}

// Position rows with the altitude AMSL last reported (within 2 s) when the row itself has none.
struct TrackPoint
{
    int64_t time;
    double latitude, longitude; // degrees
    double altitude;            // m AMSL, NaN when unknown
};

std::vector<TrackPoint> track(const FlightLog &log, int vehicle)
{
    std::vector<TrackPoint> points;
    double lat = std::nan(""), lon = std::nan(""), alt = std::nan("");
    int64_t altTime = 0;
    forEachRow(log, vehicle, [&](const Row &row) {
        const double a = row.values[size_t(TelemetryField::AltitudeAmsl)];
        if (!std::isnan(a)) {
            alt = a;
            altTime = row.time;
        }
        const double la = row.values[size_t(TelemetryField::Latitude)], lo = row.values[size_t(TelemetryField::Longitude)];
        if (std::isnan(la) && std::isnan(lo))
            return;
        if (!std::isnan(la))
            lat = la;
        if (!std::isnan(lo))
            lon = lo;
        if (std::isnan(lat) || std::isnan(lon))
            return;
        points.push_back({row.time, lat, lon, row.time - altTime <= 2000 ? alt : std::nan("")});
    });
    return points;
}

QString number(double v, int decimals)
{
    return QString::number(v, 'f', decimals);
}

void writeGpx(const FlightLog &log, const std::vector<int> &vehicles, QIODevice *out)
{
    QXmlStreamWriter xml(out);
    xml.setAutoFormatting(true);
    xml.writeStartDocument();
    xml.writeStartElement(QStringLiteral("gpx"));
    xml.writeDefaultNamespace(QStringLiteral("http://www.topografix.com/GPX/1/1"));
    xml.writeAttribute(QStringLiteral("version"), QStringLiteral("1.1"));
    xml.writeAttribute(QStringLiteral("creator"), QStringLiteral("Sortie"));
    xml.writeStartElement(QStringLiteral("metadata"));
    xml.writeTextElement(QStringLiteral("time"), utc(log.start()));
    xml.writeEndElement();
    for (int v : vehicles) {
        xml.writeStartElement(QStringLiteral("trk"));
        xml.writeTextElement(QStringLiteral("name"), log.vehicles()[size_t(v)].name());
        xml.writeStartElement(QStringLiteral("trkseg"));
        for (const TrackPoint &p : track(log, v)) {
            xml.writeStartElement(QStringLiteral("trkpt"));
            xml.writeAttribute(QStringLiteral("lat"), number(p.latitude, 8));
            xml.writeAttribute(QStringLiteral("lon"), number(p.longitude, 8));
            if (!std::isnan(p.altitude))
                xml.writeTextElement(QStringLiteral("ele"), number(p.altitude, 3));
            xml.writeTextElement(QStringLiteral("time"), utc(p.time));
            xml.writeEndElement();
        }
        xml.writeEndElement();
        xml.writeEndElement();
    }
    xml.writeEndDocument();
}

void writeKml(const FlightLog &log, const std::vector<int> &vehicles, QIODevice *out)
{
    QXmlStreamWriter xml(out);
    xml.setAutoFormatting(true);
    xml.writeStartDocument();
    xml.writeStartElement(QStringLiteral("kml"));
    xml.writeDefaultNamespace(QStringLiteral("http://www.opengis.net/kml/2.2"));
    xml.writeNamespace(QStringLiteral("http://www.google.com/kml/ext/2.2"), QStringLiteral("gx"));
    xml.writeStartElement(QStringLiteral("Document"));
    xml.writeTextElement(QStringLiteral("name"), QCoreApplication::translate("FlightLogExport", "Flight log %1").arg(utc(log.start())));
    const QString gx = QStringLiteral("http://www.google.com/kml/ext/2.2");
    for (int v : vehicles) {
        xml.writeStartElement(QStringLiteral("Placemark"));
        xml.writeTextElement(QStringLiteral("name"), log.vehicles()[size_t(v)].name());
        xml.writeStartElement(gx, QStringLiteral("Track"));
        xml.writeTextElement(QStringLiteral("altitudeMode"), QStringLiteral("absolute"));
        const std::vector<TrackPoint> points = track(log, v);
        for (const TrackPoint &p : points)
            xml.writeTextElement(QStringLiteral("when"), utc(p.time));
        for (const TrackPoint &p : points) {
            // gx:coord needs an altitude: a point without one is put on 0, which KML readers show as
            // "clamped"; it never happens with HCI or VCI telemetry, which sends altitude with position.
            xml.writeTextElement(gx, QStringLiteral("coord"), QStringLiteral("%1 %2 %3").arg(number(p.longitude, 8), number(p.latitude, 8),
                                                                                            number(std::isnan(p.altitude) ? 0 : p.altitude, 3)));
        }
        xml.writeEndElement();
        xml.writeEndElement();
    }
    xml.writeEndDocument();
}

void writeCsv(const FlightLog &log, const std::vector<int> &vehicles, QIODevice *out)
{
    std::vector<TelemetryField> columns;
    for (size_t f = 0; f < vehicle::kTelemetryFieldCount; ++f) {
        for (int v : vehicles) {
            if (log.vehicles()[size_t(v)].counts[f]) {
                columns.push_back(TelemetryField(f));
                break;
            }
        }
    }
    QTextStream s(out);
    s << "time,vehicle";
    for (TelemetryField f : columns) {
        const std::string_view unit = vehicle::fieldUnit(f);
        s << ',' << QString::fromLatin1(vehicle::fieldName(f).data(), qsizetype(vehicle::fieldName(f).size()));
        if (!unit.empty())
            s << " [" << QString::fromLatin1(unit.data(), qsizetype(unit.size())) << ']';
    }
    s << '\n';
    for (int v : vehicles) {
        QString name = log.vehicles()[size_t(v)].name();
        if (name.contains(QLatin1Char(',')) || name.contains(QLatin1Char('"')))
            name = QLatin1Char('"') + name.replace(QLatin1Char('"'), QStringLiteral("\"\"")) + QLatin1Char('"');
        forEachRow(log, v, [&](const Row &row) {
            s << utc(row.time) << ',' << name;
            for (TelemetryField f : columns) {
                s << ',';
                const double value = row.values[size_t(f)];
                if (!std::isnan(value))
                    s << QString::number(value, 'g', vehicle::isAngle(f) ? 12 : 10);
            }
            s << '\n';
        });
    }
    s.flush();
}

} // namespace

std::optional<ExportFormat> exportFormatFromName(const QString &name)
{
    const QString n = name.toLower();
    if (n == QLatin1String("gpx"))
        return ExportFormat::Gpx;
    if (n == QLatin1String("kml"))
        return ExportFormat::Kml;
    if (n == QLatin1String("csv"))
        return ExportFormat::Csv;
    return std::nullopt;
}

QString exportSuffix(ExportFormat format)
{
    switch (format) {
    case ExportFormat::Gpx: return QStringLiteral("gpx");
    case ExportFormat::Kml: return QStringLiteral("kml");
    case ExportFormat::Csv: return QStringLiteral("csv");
    }
    return {};
}

bool exportLog(const FlightLog &log, ExportFormat format, const std::vector<int> &vehicles, QIODevice *out, QString *error)
{
    std::vector<int> chosen = vehicles;
    if (chosen.empty()) {
        for (size_t i = 0; i < log.vehicles().size(); ++i)
            chosen.push_back(int(i));
    }
    switch (format) {
    case ExportFormat::Gpx: writeGpx(log, chosen, out); break;
    case ExportFormat::Kml: writeKml(log, chosen, out); break;
    case ExportFormat::Csv: writeCsv(log, chosen, out); break;
    }
    if (auto *file = qobject_cast<QFileDevice *>(out); file && file->error() != QFileDevice::NoError) {
        if (error)
            *error = file->errorString();
        return false;
    }
    return true;
}

} // namespace sortie::flightlog
